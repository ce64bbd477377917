// `helix` (Cook et al. 2004, Fig. 8): two coiled tubes on the same (z) axis and with the
// same pitch, a thin inner tube (coil radius 1, tube radius 0.35, scalars 0.2..0.3) inside a
// thicker outer one (coil radius 2.4, tube radius 0.6, scalars 0.7..0.8, half a turn out of
// phase). At least 0.44 units of empty space separate them everywhere, and from most views
// each tube hides the other across it: the case where centroid sorting (MPVONC) fails.
// Each tube is a disk of `rings` rings x `sectors` sectors (triangulated) swept along the
// helix in `steps` steps with a rotation-minimising frame; every swept triangle is a prism
// cut into three tetrahedra with the conforming min-id rule (prism_split.h).
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

struct HelixResolution {
  int sectors = 3, rings = 1, steps = 1;
  int64_t cells() const { return int64_t(2) * 3 * sectors * (2 * rings - 1) * steps; }
};
// The resolution whose cell count is nearest `cells` with near-isotropic cells and at
// least 6 steps per turn. InputError when `cells` is below the smallest helix.
HelixResolution helix_resolution(int cells, int turns);
int helix_min_cells(int turns);

struct HelixSpec {
  int cells = 20000, turns = 3;
  Vec3 offset{0, 0, 0};  // added to every coordinate (the `offset` hard case)
};
CellMesh make_helix_mesh(const HelixSpec& s);
Scene make_helix(Params& p);  // cells=20000 turns=3

}  // namespace vob
