// The one helper of meshes, cameras and order checks built in code for the tests and
// benchmarks (tests/support, library vob_test_support), so that no test depends on the
// dataset generators for its basic scenes.
#pragma once
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob::test {

// ---- Blocks of Kuhn tetrahedra and hexahedra ----
// nx * ny * nz cubes of side h from `origin`, each split into the 6 tets around its main
// diagonal (Kuhn), so neighbouring cubes split shared faces alike: conforming and convex.
// Point i + (nx+1)*(j + (ny+1)*k); cell 6*c + t is tet t of cube c = i + nx*(j + ny*k).
CellMesh tet_block(int nx, int ny, int nz, Vec3 origin = {}, double h = 1.0);
// The n^3 tet_block with a scalar per point (test_scalar) and, with jitter > 0, interior
// points moved by up to jitter * h per axis (deterministic for a seed).
CellMesh kuhn_block(int n, double h = 1.0, double jitter = 0, uint32_t seed = 1);
// kuhn_block(n), validated, as the scene "tet block".
Scene kuhn_block_scene(int n);
// An n^3 block of axis-aligned hexahedra with scalars. Cell i + n*(j + n*k).
CellMesh hex_block(int n, double h = 1.0);
// An n x n x layers bar of unit hexahedra along z, centred on the z axis, layer k's points
// turned by k * twist radians about the axis (as gmsh extrudes with a rotation): the side
// quads are not planar, warped by about twist / 2 of their size. Cell i + n*(j + n*k).
CellMesh twisted_hex_bar(int n, int layers, double twist);
// twisted_hex_bar(2, layers, twist) with points (2,1) and (1,0) of each layer exchanged, so
// that around the axis the oracle anchors the quads towards +-x at an outer bottom point and
// those towards +-y at the axis's bottom point (each face plane passes through its smallest
// point id, cell_planes.h): the two planes of each cell at the axis are then shifted
// against each other by about twist / 2, and the neighbours in quadrants I and III (cells 0
// and 3 of each layer), which share only the axis edge, overlap as the oracle models them
// in a sliver about twist / 2 thick. In the natural numbering the shifts cancel and they
// only touch.
CellMesh overlapping_twisted_bar(int layers, double twist);
double test_scalar(Vec3 p);

// ---- Composition ----
// `a` then `b`, b's points duplicated (its point and cell ids shifted; scalars kept).
CellMesh append(const CellMesh& a, const CellMesh& b);
CellMesh translated(CellMesh m, Vec3 by);
// Every point turned by `angle` radians about the unit `axis` through the origin (in
// doubles: planar faces stay planar only up to rounding).
CellMesh rotated(CellMesh m, Vec3 axis, double angle);
// Two n^3 blocks of unit cubes side by side along x, `gap` apart; block A holds cells
// [0, 6n^3), block B the rest.
CellMesh two_blocks(int n, double gap);
// One positively oriented tetrahedron per call, on its own (duplicated) points.
void add_tet(CellMesh& m, Vec3 a, Vec3 b, Vec3 c, Vec3 d);
CellMesh tet_pair(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e, Vec3 f, Vec3 g, Vec3 h);
// Two n^3 Kuhn blocks that interpenetrate: the second moved by (n/2 + 0.25, 0.3, 0.2) * h.
CellMesh interpenetrating_blocks(int n, double h = 1.0);
// A ring of `sectors` wedges around the z axis (radii 1..2, height 1) whose shared
// triangular faces are tilted like propeller blades: from any eye on the +z axis each
// wedge is in front of the previous one across their face, a cyclic overlap.
CellMesh blade_ring(int sectors);

// ---- Cameras ----
Camera ring_axis_view(bool ortho);  // looking down blade_ring's axis
// Looking from eye at target, z up unless the view is along z.
Camera test_camera(Vec3 eye, Vec3 target, int w, int h, bool ortho = false, double ortho_height = 2.0);

// ---- Known orders and checks ----
// Depth key of a point for a view: larger is farther. Sorting the cubes of a regular grid
// by it is exact (the grid is the Voronoi diagram of the cube centres).
double view_key(const Camera& cam, Vec3 p);
// Exact back-to-front order of kuhn_block(n) (unjittered) for `cam`: cubes by decreasing
// distance, the 6 tets of a cube topologically sorted by their shared faces.
std::vector<int32_t> tet_block_exact_order(const CellMesh& m, int n, const Camera& cam);

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

}  // namespace vob::test

// The algorithm tests' older name for the same helpers.
namespace vob::testing {
using namespace vob::test;
}  // namespace vob::testing
