// Hard cases about the mesh itself (hard_case = true in the registry):
//   offset   a small helix (or gap block) moved by `offset` (default 1e7) on every axis, so
//            coordinates carry few significant bits for the cell sizes.
//   slivers  an n x n slab whose middle layer is n*n near-flat sliver tetrahedra (corners
//            at z = +-flatness, checkerboard), filled above and below by prisms cut into
//            tetrahedra: valid in exact arithmetic, dihedral angles near 0 and 180 degrees.
//   tiny     `count` tetrahedra of edge about `size` (relative to the unit cube they are
//            scattered in, one per jittered grid cell, so they never overlap): at 512x512
//            most cover no pixel centre.
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

Scene make_offset(Params& p);   // shape=helix offset=1e7
Scene make_slivers(Params& p);  // n=8 flatness=1e-6
Scene make_tiny(Params& p);     // count=2000 size=0.001 seed=1

}  // namespace vob
