// A regular block of hexahedra, each split into six tetrahedra around its (0,0,0)-(1,1,1)
// diagonal (the Kuhn/Freudenthal split). The split is translation invariant, so two
// neighbouring hexahedra split their shared quad along the same diagonal: the result is
// conforming. Face planes are the axis planes and the planes x=y, y=z, x=z (shifted).
#pragma once
#include <cstdint>

#include "harness/scene/cell_mesh.h"

namespace vob {

struct BlockSpec {
  int nx = 1, ny = 1, nz = 1;  // hexahedra per axis
  Vec3 origin{0, 0, 0};
  Vec3 spacing{1, 1, 1};
};

// Appends (nx+1)(ny+1)(nz+1) points and 6*nx*ny*nz positively oriented tetrahedra.
// Returns the id of the block's first point; point (i,j,k) is first + i + (nx+1)(j + (ny+1)k).
// Scalars are not touched (the caller sizes and fills them).
int32_t append_kuhn_block(CellMesh& m, const BlockSpec& b);

}  // namespace vob
