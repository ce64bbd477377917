// INRIMAGE-4 volumes (.inr, and gzipped .inr.gz): a text header of 256-byte blocks from
// "#INRIMAGE-4#{" to "##}", then raw samples, x fastest. Supported: VDIM=1;
// TYPE=unsigned fixed / signed fixed (PIXSIZE 8, 16, 32 bits) or float (32, 64 bits);
// CPU=decm|pc|alpha (little endian) or sun|sgi (big endian); XDIM/YDIM/ZDIM; VX/VY/VZ
// (spacing, default 1); SCALE is recorded by the format for fixed-point data and ignored
// (values are the raw integers). Origin 0; threshold 0 (values > 0 are significant).
#pragma once
#include <string>

#include "harness/scene/voxel_grid.h"

namespace vob {

VoxelGrid read_inr(const std::string& path);
VoxelGrid read_inr_gz(const std::string& path);  // the whole file inflated with zlib first

}  // namespace vob
