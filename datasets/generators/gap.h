// `gap` (Cook et al. 2004, section 5.2 and Fig. 11-13): an nx x ny x nz block of unit
// hexahedra, each split into six tetrahedra (conforming Kuhn split), sliced along z into
// gaps+1 slabs like bread. The slabs hold nz/(gaps+1) hexahedron layers each (the first
// nz % (gaps+1) slabs one more) and are moved apart so that every gap is kGapWidth = 0.5
// units of empty space parallel to the ends. The cell count stays 6*nx*ny*nz; each gap adds
// 4*nx*ny exterior triangles.
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

constexpr double kGapWidth = 0.5;

struct GapSpec {
  int nx = 50, ny = 50, nz = 100, gaps = 0;
  Vec3 offset{0, 0, 0};  // added to every coordinate (the `offset` hard case)
};
CellMesh make_gap_mesh(const GapSpec& s);
Scene make_gap(Params& p);  // nx=50 ny=50 nz=100 gaps=0

}  // namespace vob
