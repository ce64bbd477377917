// XMPVO's double filters (uv_filter.h, plane_keys.h): every sign they call certain is the
// exact predicate's, on random and on exactly degenerate input, perspective and
// orthographic; they decide most random cases; XMPVO counts what they left to the exact
// predicates and orders as without them (compare mode runs no filter).
#include <gtest/gtest.h>

#include <random>

#include "algorithms/xmpvo/face_pairs.h"
#include "algorithms/xmpvo/plane_keys.h"
#include "algorithms/xmpvo/projection.h"
#include "algorithms/xmpvo/uv_filter.h"
#include "datasets/datasets.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::xmpvo;
using namespace vob::test;

namespace {

// Random triangles in [-1, 1]^3 after two slivers (0, 1, 3) and (0, 2, 3) in z = 0 whose
// points 0, 1, 2 lie exactly on the x axis and 3 is 1e-13 off it.
ExteriorFaces random_faces(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  ExteriorFaces e;
  e.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, 1e-13, 0}};
  for (int i = 0; i < 3 * n; ++i) e.points.push_back({u(rng), u(rng), u(rng)});
  for (int f = 0; f < n + 2; ++f) {
    const int32_t b = 4 + 3 * (f - 2);
    const int32_t v[3] = {f < 2 ? 0 : b, f < 2 ? 1 + f : b + 1, f < 2 ? 3 : b + 2};
    e.face.push_back(f);
    e.size.push_back(3);
    e.cell.push_back(f);
    for (int k = 0; k < 4; ++k) e.vertex.push_back(k < 3 ? v[k] : -1);
    for (int k = 0; k < 4; ++k) e.corners.push_back(k < 3 ? e.points[v[k]] : Vec3{});
  }
  return e;
}

Camera camera(bool ortho, Vec3 eye) {
  Camera c;
  c.eye = eye;
  c.ortho = ortho;
  return c;
}

}  // namespace

TEST(XmpvoDoubleFilters, SidesAgreeWithExactAndDegeneratesAreLeftToIt) {
  std::mt19937 rng(7);
  const ExteriorFaces e = random_faces(300, rng);
  int decided = 0, total = 0;
  for (const Camera& cam : {camera(false, {0.3, 0.2, 6}), camera(true, {2, -3, 5}), camera(false, {-4, 1, -3})}) {
    Signs signs;
    signs.g = ViewGeometry::of(cam);
    Projection proj;
    proj.run(e, cam, signs, {0, 0, 0}, 2);
    ASSERT_TRUE(proj.uv_filter);
    const int32_t n = static_cast<int32_t>(e.points.size());
    std::uniform_int_distribution<int32_t> pick(0, n - 1);
    for (int i = 0; i < 20000; ++i) {
      const int32_t x = pick(rng), p = pick(rng), q = pick(rng);
      if (!proj.point_used[x] || !proj.point_used[p] || !proj.point_used[q] || x == p || p == q || x == q) continue;
      const int s = uv_side(proj.uv[x], proj.uv[p], proj.uv[q], proj.slack);
      ++total;
      if (s == 2) continue;
      ++decided;
      ASSERT_EQ(proj.sign_n * s, edge_side(signs.g, e.points[x], e.points[p], e.points[q])) << x << " " << p << " " << q;
    }
    // Exactly collinear: the filter cannot be sure and says so; 1e-13 off the line too.
    EXPECT_EQ(edge_side(signs.g, e.points[0], e.points[1], e.points[2]), 0);
    EXPECT_EQ(uv_side(proj.uv[2], proj.uv[0], proj.uv[1], proj.slack), 2);
    const int near = uv_side(proj.uv[3], proj.uv[0], proj.uv[1], proj.slack);
    EXPECT_TRUE(near == 2 || proj.sign_n * near == edge_side(signs.g, e.points[0], e.points[1], e.points[3]));
  }
  EXPECT_GT(decided, 0.95 * total);
}

TEST(XmpvoDoubleFilters, PlaneKeysAgreeWithExactPlaneOrder) {
  std::mt19937 rng(11);
  const ExteriorFaces e = random_faces(200, rng);
  std::vector<FacePlane> plane;
  for (size_t f = 0; f < e.face.size(); ++f) plane.push_back(FacePlane::of(&e.corners[4 * f]));
  std::uniform_int_distribution<size_t> pick(0, e.face.size() - 1);
  std::uniform_real_distribution<double> u(-1, 1);
  int decided = 0, total = 0;
  for (const Camera& cam : {camera(false, {0.3, 0.2, 6}), camera(true, {2, -3, 5})}) {
    const ViewGeometry g = ViewGeometry::of(cam);
    std::vector<ViewPlane> vp;
    for (const FacePlane& p : plane) vp.push_back(ViewPlane::of(g, p));
    for (int i = 0; i < 3000; ++i) {
      const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)}, d{u(rng), u(rng), u(rng)};
      const bool crossing = i % 2 && edge_side(g, c, d, a) * edge_side(g, c, d, b) < 0;
      const VertexRay r = crossing ? VertexRay::at_crossing(g, a, b, c, d) : VertexRay::at_point(g, a);
      const RayTerms t = RayTerms::of(r);
      const size_t x = pick(rng), y = i % 7 ? pick(rng) : x;  // y == x: equal keys
      const int k = compare_keys(plane_key(g, t, vp[x]), plane_key(g, t, vp[y]));
      ++total;
      if (k == 2) continue;
      ++decided;
      ASSERT_EQ(k, vertex_plane_order(r, plane[x], plane[y])) << i;
    }
  }
  EXPECT_GT(decided, 0.8 * total);
}

// The filters decide nearly every sign on a helix; the order is compare mode's, which uses
// no filter (every side decision there goes to the exact predicate).
TEST(XmpvoDoubleFilters, XmpvoCountsFilteredAndRecheckedDecisions) {
  const Scene s = dataset("helix", {{"cells", "2000"}});
  const Camera view = fibonacci_view(s.bounds(), 14, 5, ViewOptions{200, 200});
  const Outcome exact = run_checked("xmpvo", s, view), compare = run_checked("xmpvo:predicates=compare", s, view);
  EXPECT_TRUE(exact.oracle.ok());
  EXPECT_EQ(exact.ordering.order, compare.ordering.order);
  const auto& k = exact.ordering.counters;
  EXPECT_GT(k.at("side_filtered"), 100 * (k.at("side_rechecked") + 1));
  EXPECT_EQ(k.at("crossings_filtered") + k.at("crossings_rechecked"), k.at("candidate_edge_pairs"));
  EXPECT_LE(k.at("queries_rechecked"), k.at("vertex_queries"));
  const auto& c = compare.ordering.counters;
  EXPECT_EQ(c.at("side_filtered"), 0);
  EXPECT_EQ(c.at("crossings_filtered"), 0);
}
