// stencil-xmpvo's snapped face signs (algorithms/stencil/snapped_signs.h) on two tets that
// share a face seen almost edge-on: its projection is a sliver whose third vertex lies
// 1/10000 pixel on one side of the other two's line, and 1/256-pixel snapping puts it on
// the other side. The shared face's arrow must then follow the snapped winding, which is
// the exact sign of the mesh whose points sit where llvmpipe snaps them; seen from a view
// where the face is no sliver, nothing flips.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/stencil/snapped_signs.h"
#include "harness/bench/phase_clock.h"
#include "harness/raster/raster_rule.h"
#include "harness/raster/sample_frame.h"

using namespace vob;

namespace {

// Points a, b, c (the shared face), d and e on either side; cells (a, b, c, d), (a, b, c, e).
CellMesh two_tets(const std::vector<Vec3>& p) {
  CellMesh m;
  m.points = p;
  for (int32_t apex : {3, 4}) {
    int32_t b = 1, c = 2;
    if (dot(cross(p[1] - p[0], p[2] - p[0]), p[size_t(apex)] - p[0]) < 0) std::swap(b, c);
    m.add_cell(CellType::Tetra, {0, b, c, apex});
  }
  return m;
}

// An orthographic view along -z, one pixel per unit: window x = x + 32, y = y + 32.
Camera along_z() {
  Camera c;
  c.eye = {0, 0, 10};
  c.ortho = true;
  c.ortho_height = 64;
  c.width = c.height = 64;
  return c;
}

std::vector<int8_t> signs(const CellMesh& m, const Camera& view, bool snapped, int64_t* flips = nullptr) {
  mpvo::MpvoCore core;
  PhaseClock clock;
  core.prepare(Scene::from_mesh("two tets", m), clock);
  core.create_partial_order(view);
  std::vector<int64_t> scratch;
  const int64_t n = snapped ? stencil::apply_snapped_signs(core, view, scratch) : 0;
  if (flips) *flips = n;
  return core.face_signs();
}

}  // namespace

TEST(StencilSnappedSigns, AnEdgeOnFaceFollowsItsSnappedWinding) {
  // c is 0.0001 above the line through a and b at x = 0; c.y snaps down, b.y up.
  const std::vector<Vec3> p = {{-10, 0, 0}, {10, 0.003, 0}, {0, 0.0016, 5}, {0, 8, 2}, {0, -8, 2}};
  const Camera view = along_z();
  const SampleFrame frame(view, 1);
  std::vector<Vec3> snapped = p;  // where llvmpipe puts them: window - 32 on the 1/256 grid
  for (Vec3& q : snapped) {
    double x, y, zc;
    ASSERT_TRUE(frame.project(q, x, y, zc));
    q.x = gl_unsnap(gl_snap(x)) - 32;
    q.y = gl_unsnap(gl_snap(y)) - 32;
  }
  ASSERT_GT(snapped[1].y, p[1].y);  // the construction: b moves up, c down
  ASSERT_LT(snapped[2].y, p[2].y);
  int64_t flips = 0;
  const std::vector<int8_t> exact = signs(two_tets(p), view, false);
  const std::vector<int8_t> ours = signs(two_tets(p), view, true, &flips);
  const std::vector<int8_t> truth = signs(two_tets(snapped), view, false);
  EXPECT_EQ(flips, 1);
  EXPECT_NE(ours, exact);
  EXPECT_EQ(ours, truth);  // every face as the snapped mesh has it
  // Seen from the side (along -y, where the face spans 20 x 5 pixels) nothing flips.
  Camera side = view;
  side.eye = {0.3, -10, 0.2};
  side.target = {0.3, 0, 0.2};
  side.up = {0, 0, 1};
  EXPECT_EQ(signs(two_tets(p), side, true, &flips), signs(two_tets(p), side, false));
  EXPECT_EQ(flips, 0);
}
