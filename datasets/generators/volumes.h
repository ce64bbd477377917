// Synthetic voxel volumes on an nx x ny x nz grid (spacing 1, origin 0; default 64^3).
// Empty space is exactly 0 and the threshold is 0, so every voxel of material (value > 0)
// is significant and nothing else is.
//   block   a dense machined block in the spirit of the classic "engine" CT: a solid slab
//           with two vertical bores, a horizontal cross bore and a closed inner chamber
//           (about 30% of the voxels are material).
//   shells  a solid ball inside two concentric shells, plus eight small balls in the
//           corners (about 14%).
//   sparse  `blobs` small soft balls scattered at random (seeded) plus a thin helical wire:
//           a volume that is mostly empty space (about 1-2%).
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

Scene make_block_volume(Params& p);   // nx=64 ny=64 nz=64
Scene make_shells_volume(Params& p);  // nx=64 ny=64 nz=64
Scene make_sparse_volume(Params& p);  // nx=64 ny=64 nz=64 blobs=40 seed=1

}  // namespace vob
