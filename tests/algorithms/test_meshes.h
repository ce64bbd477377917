// Small meshes built in code for the algorithm tests and benchmarks, plus a brute-force
// per-ray ordering check that needs no oracle.
#pragma once
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob::testing {

// nx * ny * nz cubes of side h from `origin`, each split into 6 tets around the same
// diagonal (Kuhn), so neighbouring cubes split shared faces alike: conforming and convex.
CellMesh tet_block(int nx, int ny, int nz, Vec3 origin = {}, double h = 1.0);
// `a` then `b` (b's point and cell ids shifted).
CellMesh append(const CellMesh& a, const CellMesh& b);
// Two n^3 blocks of unit cubes side by side along x, `gap` apart; block A holds cells
// [0, 6n^3), block B the rest.
CellMesh two_blocks(int n, double gap);
// A ring of `sectors` wedges around the z axis (radii 1..2, height 1) whose shared
// triangular faces are tilted like propeller blades: from any eye on the +z axis each
// wedge is in front of the previous one across their face, a cyclic overlap.
CellMesh blade_ring(int sectors);
Camera ring_axis_view(bool ortho);  // looking down the ring's axis

// Cells along each pixel-centre ray (positive-length segments, from the face planes), and
// the pairs (nearer, farther) of cells on one ray that `order` draws nearer-first.
struct RayCheck {
  int64_t rays_hit = 0;
  int64_t pairs_checked = 0;
  std::set<std::pair<int32_t, int32_t>> violations;  // (drawn too early, drawn too late)
};
RayCheck ray_check(const Scene& scene, const Camera& view, const std::vector<int32_t>& order);

// Shared faces whose exact sidedness (orient3d / orient_direction) puts the cell behind
// later in `order` than the cell in front: MPVO's arrows violated.
int64_t face_arrow_violations(const Scene& scene, const Camera& view,
                              const std::vector<int32_t>& order);

// True when `order` holds every id in [0, n) exactly once.
bool is_permutation_of(const std::vector<int32_t>& order, size_t n);

}  // namespace vob::testing
