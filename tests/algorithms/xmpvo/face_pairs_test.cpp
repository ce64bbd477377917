// Exact exterior-face geometry of XMPVO / BSP-XMPVO (algorithms/xmpvo/face_pairs.h):
// sides, projected overlap (open overlap only), depth order including faces that each
// straddle the other's plane, crossing sides; perspective and orthographic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "algorithms/xmpvo/face_pairs.h"
#include "harness/geometry/predicates.h"

using namespace vob;
using namespace vob::xmpvo;

namespace {

// Looking down -z from z = 10 (perspective) or along -z (orthographic).
ViewGeometry persp(Vec3 eye = {0.3, 0.2, 10}) {
  ViewGeometry g;
  g.eye = eye;
  g.dir = {0, 0, -1};
  return g;
}
ViewGeometry ortho() {
  ViewGeometry g;
  g.ortho = true;
  g.eye = {0, 0, 10};
  g.dir = {0, 0, -1};
  return g;
}

// Triangle in the plane z = h, counter-clockwise seen from +z.
struct Tri {
  Vec3 v[3];
};
Tri tri(double x0, double y0, double x1, double y1, double x2, double y2, double h) {
  return {{{x0, y0, h}, {x1, y1, h}, {x2, y2, h}}};
}

TEST(FacePairs, ViewGeometryFromCamera) {
  Camera c;
  c.eye = {1, 2, 3};
  c.target = {1, 2, 0};
  c.ortho = true;
  const ViewGeometry g = ViewGeometry::of(c);
  EXPECT_TRUE(g.ortho);
  EXPECT_EQ(g.dir.z, -1.0);
  EXPECT_EQ(g.eye.x, 1.0);
}

TEST(FacePairs, EdgeSideAndEyeSideConventions) {
  for (const ViewGeometry& g : {persp(), ortho()}) {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_EQ(eye_side(g, a, b, c), 1);   // normal +z, eye above
    EXPECT_EQ(eye_side(g, a, c, b), -1);
    EXPECT_EQ(edge_side(g, a, b, c), -eye_side(g, a, b, c));
    EXPECT_EQ(edge_side_double(g, a, b, c), edge_side(g, a, b, c));
    EXPECT_EQ(eye_side_double(g, a, b, c), eye_side(g, a, b, c));
    // A face seen edge-on: its plane holds the view direction / the eye.
    const Vec3 e = g.ortho ? Vec3{0, 0, 1} : g.eye;
    EXPECT_EQ(eye_side(g, a, b, a + e), 0);
  }
  // Orthographic: a point straight below the edge's line projects onto it.
  EXPECT_EQ(edge_side(ortho(), {0, 0, 0}, {1, 0, 0}, {0.5, 0, -7}), 0);
  // Perspective: on the plane through the eye and the edge.
  const ViewGeometry g = persp({0, 0, 10});
  EXPECT_EQ(edge_side(g, {0, 0, 0}, {1, 0, 0}, {0.25, 0, 5}), 0);
  EXPECT_NE(edge_side(g, {0, 0, 0}, {1, 0, 0}, {0.25, 0.001, 5}), 0);
}

TEST(FacePairs, OverlapTouchingDisjoint) {
  for (const ViewGeometry& g : {persp({0, 0, 10}), ortho()}) {
    const Tri a = tri(0, 0, 1, 0, 0, 1, 0);
    const Tri inside = tri(0.1, 0.1, 0.2, 0.1, 0.1, 0.2, -1);  // contained in a's projection
    const Tri cross = tri(0.4, 0.4, 2, 0.4, 0.4, 2, 0);        // overlaps a's corner
    const Tri edge = tri(1, 0, 1, 1, 0, 1, 0);                 // shares a's hypotenuse
    const Tri point = tri(1, 0, 2, 0, 2, 1, 0);                // shares a's vertex (1, 0)
    const Tri far = tri(5, 5, 6, 5, 5, 6, 0);
    EXPECT_TRUE(projections_overlap(g, a.v, 3, inside.v, 3));
    EXPECT_TRUE(projections_overlap(g, inside.v, 3, a.v, 3));
    EXPECT_TRUE(projections_overlap(g, a.v, 3, cross.v, 3));
    EXPECT_FALSE(projections_overlap(g, a.v, 3, edge.v, 3));
    EXPECT_FALSE(projections_overlap(g, a.v, 3, point.v, 3));
    EXPECT_FALSE(projections_overlap(g, a.v, 3, far.v, 3));
    // Winding does not matter (back-facing faces).
    const Vec3 rev[3] = {cross.v[0], cross.v[2], cross.v[1]};
    EXPECT_TRUE(projections_overlap(g, a.v, 3, rev, 3));
    // A quad against a triangle touching one of its edges.
    const Vec3 quad[4] = {{-1, -1, 0}, {0, -1, 0}, {0, 0.5, 0}, {-1, 0.5, 0}};
    EXPECT_FALSE(projections_overlap(g, a.v, 3, quad, 4));
    const Vec3 quad2[4] = {{-1, -1, 0}, {0.01, -1, 0}, {0.01, 0.5, 0}, {-1, 0.5, 0}};
    EXPECT_TRUE(projections_overlap(g, a.v, 3, quad2, 4));
  }
  // Perspective: the same two triangles at different depths overlap or not depending on
  // where the eye is, which the orthographic projection would never show.
  const Tri near = tri(0, 0, 1, 0, 0, 1, 5);  // halfway to the eye: projects twice as large
  const Tri far = tri(1.2, 0.1, 1.9, 0.1, 1.2, 0.8, 0);
  EXPECT_TRUE(projections_overlap(persp({0, 0, 10}), near.v, 3, far.v, 3));
  EXPECT_FALSE(projections_overlap(ortho(), near.v, 3, far.v, 3));
  // An edge-on face covers no open set.
  const Vec3 edge_on[3] = {{0.1, 0.1, 0}, {0.3, 0.1, 0}, {0.1, 0.1, -2}};
  EXPECT_FALSE(projections_overlap(ortho(), near.v, 3, edge_on, 3));
}

TEST(FacePairs, DepthOrderByPlanes) {
  for (const ViewGeometry& g : {persp(), ortho()}) {
    const Tri top = tri(0, 0, 1, 0, 0, 1, 1);
    const Tri bottom = tri(0, 0, 1, 0, 0, 1, 0);
    EXPECT_EQ(depth_order(g, top.v, 3, bottom.v, 3), -1);
    EXPECT_EQ(depth_order(g, bottom.v, 3, top.v, 3), 1);
    // Tilted faces sharing an edge's projection range, one below the other.
    const Vec3 tilt[3] = {{0, 0, 0.5}, {1, 0, -0.5}, {0, 1, 0.5}};
    EXPECT_EQ(depth_order(g, top.v, 3, tilt, 3), -1);
    EXPECT_EQ(depth_order(g, tilt, 3, bottom.v, 3), 0);  // they cross along x = 0.5
    // Touching at a vertex that lies on the other face's plane still orders them.
    const Vec3 tent[3] = {{0.2, 0.2, 0}, {2, 0.2, 2}, {0.2, 2, 2}};
    EXPECT_EQ(depth_order(g, tent, 3, bottom.v, 3), -1);
    // Coplanar overlapping faces cannot be ordered.
    const Tri same = tri(0.2, 0.2, 1, 0.2, 0.2, 1, 0);
    EXPECT_EQ(depth_order(g, bottom.v, 3, same.v, 3), 0);
  }
}

TEST(FacePairs, DepthOrderStraddlingSticks) {
  // Two long planar quads crossed like sticks: A on z = x + 1, B on z = y. Each straddles
  // the other's plane; over their overlap near the origin A is at z ~ 1, B at z ~ 0.
  const Vec3 a[4] = {{-2, -0.1, -1}, {2, -0.1, 3}, {2, 0.1, 3}, {-2, 0.1, -1}};
  const Vec3 b[4] = {{-0.1, -2, -2}, {0.1, -2, -2}, {0.1, 2, 2}, {-0.1, 2, 2}};
  for (const ViewGeometry& g : {persp(), ortho()}) {
    ASSERT_TRUE(projections_overlap(g, a, 4, b, 4));
    EXPECT_EQ(depth_order(g, a, 4, b, 4), -1);
    EXPECT_EQ(depth_order(g, b, 4, a, 4), 1);
  }
  // Seen from below (eye at z = -10) the order flips.
  ViewGeometry below = persp({0.3, 0.2, -10});
  below.dir = {0, 0, 1};
  EXPECT_EQ(depth_order(below, a, 4, b, 4), 1);
  ViewGeometry below_ortho = ortho();
  below_ortho.dir = {0, 0, 1};
  EXPECT_EQ(depth_order(below_ortho, a, 4, b, 4), 1);
  // B lifted by 1 passes through A at the origin: intersecting faces are undecidable.
  const Vec3 b_up[4] = {{-0.1, -2, -1}, {0.1, -2, -1}, {0.1, 2, 3}, {-0.1, 2, 3}};
  EXPECT_EQ(depth_order(ortho(), a, 4, b_up, 4), 0);
  EXPECT_EQ(depth_order(persp(), a, 4, b_up, 4), 0);
}

TEST(FacePairs, CrossingSideExactAndDegenerate) {
  // Orthographic along z: (a, b) and (c, d) cross at the projected origin, at different
  // heights; the line through (-1, -1) and (1, 1) passes exactly through the crossing.
  const ViewGeometry g = ortho();
  const Vec3 a{-1, 0, 0}, b{1, 0, 5}, c{0, -1, 2}, d{0, 1, 7};
  ASSERT_EQ(edge_side(g, c, d, a) * edge_side(g, c, d, b), -1);
  EXPECT_EQ(crossing_side(g, a, b, c, d, Vec3{-1, -1, 3}, Vec3{1, 1, -4}), 0);
  EXPECT_EQ(crossing_side(g, a, b, c, d, Vec3{-1, -1, 3}, Vec3{1, 1.001, -4}), 1);
  EXPECT_EQ(crossing_side(g, a, b, c, d, Vec3{-1, -1, 3}, Vec3{1, 0.999, -4}), -1);
  // Symmetric in which of the two crossing edges is named first.
  EXPECT_EQ(crossing_side(g, c, d, a, b, Vec3{-1, -1, 3}, Vec3{1, 1.001, -4}), 1);
  // Perspective: a crossing off the eye's axis agrees with the projected-plane computation.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const ViewGeometry p = persp({0.1, -0.2, 8});
  int tested = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Vec3 q[6];
    for (auto& v : q) v = {u(rng), u(rng), u(rng)};
    if (edge_side(p, q[2], q[3], q[0]) * edge_side(p, q[2], q[3], q[1]) >= 0) continue;
    // The crossing in the image plane z = 0, by doubles; far from the third line only.
    // Looking down -z, D's sign is minus the xy orientation.
    auto proj = [&](Vec3 x) {
      const double s = 8 / (8 - x.z);
      return Vec3{0.1 + (x.x - 0.1) * s, -0.2 + (x.y + 0.2) * s, 0};
    };
    auto orient2 = [](Vec3 o, Vec3 x, Vec3 y) {
      return (x.x - o.x) * (y.y - o.y) - (x.y - o.y) * (y.x - o.x);
    };
    const Vec3 A = proj(q[0]), B = proj(q[1]), C = proj(q[2]), D = proj(q[3]);
    const double oa = orient2(C, D, A), ob = orient2(C, D, B);
    const Vec3 X = A + (B - A) * (oa / (oa - ob));
    const double ref = orient2(X, proj(q[4]), proj(q[5]));
    if (std::fabs(ref) < 1e-6) continue;
    EXPECT_EQ(crossing_side(p, q[0], q[1], q[2], q[3], q[4], q[5]), ref > 0 ? -1 : 1);
    EXPECT_EQ(crossing_side_double(p, q[0], q[1], q[2], q[3], q[4], q[5]), ref > 0 ? -1 : 1);
    ++tested;
  }
  EXPECT_GT(tested, 200);
}

}  // namespace

namespace {

// Plane order along a vertex ray agrees with depth_order for faces covering that ray, is 0
// where they touch on it, and the cached VertexRay / FacePlane forms agree with the plain
// ones, for points and crossings, perspective and orthographic.
TEST(FacePairs, PlaneOrderAtVertexRays) {
  const Vec3 a[4] = {{-2, -0.1, -1}, {2, -0.1, 3}, {2, 0.1, 3}, {-2, 0.1, -1}};  // z = x + 1
  const Vec3 b[4] = {{-0.1, -2, -2}, {0.1, -2, -2}, {0.1, 2, 2}, {-0.1, 2, 2}};  // z = y
  const FacePlane pa = FacePlane::of(a), pb = FacePlane::of(b);
  for (const ViewGeometry& g : {persp(), ortho()}) {
    // A point on A's plane inside both projections (near the origin): A is hit first.
    const Vec3 p{0.01, 0.02, 1.01};
    EXPECT_EQ(plane_order_at(g, a, b, p), -1);
    EXPECT_EQ(plane_order_at(g, b, a, p), 1);
    EXPECT_EQ(vertex_plane_order(VertexRay::at_point(g, p), pa, pb), -1);
    EXPECT_EQ(plane_order_at(g, a, a, p), 0);
    // The crossing of A's edge (a0, a1) with B's edge (b1, b2) in projection.
    ASSERT_EQ(edge_side(g, b[1], b[2], a[0]) * edge_side(g, b[1], b[2], a[1]), -1);
    const VertexRay x = VertexRay::at_crossing(g, a[0], a[1], b[1], b[2]);
    EXPECT_EQ(plane_order_at_crossing(g, a, b, a[0], a[1], b[1], b[2]), -1);
    EXPECT_EQ(vertex_plane_order(x, pa, pb), -1);
    EXPECT_EQ(vertex_plane_order(x, pb, pa), 1);
    // Sides from the crossing: its own edge's line holds it; other points agree.
    EXPECT_EQ(vertex_side(x, a[0], a[1]), 0);
    EXPECT_EQ(vertex_side(x, b[1], b[2]), 0);
    for (const Vec3& q : {a[2], a[3], b[0], b[3], Vec3{5, 5, 0}})
      EXPECT_EQ(vertex_side(x, a[2], q), crossing_side(g, a[0], a[1], b[1], b[2], a[2], q));
    const VertexRay at = VertexRay::at_point(g, p);
    EXPECT_EQ(vertex_side(at, a[0], a[1]), edge_side(g, a[0], a[1], p));
  }
}

}  // namespace

// Volumes touching face to face: the upper block's bottom (outward normal -z) and the lower
// block's top (outward normal +z) lie in one plane. Seen from above the ray leaves the
// upper cell through its back-facing bottom and then enters the lower cell through its
// front-facing top, so the back-facing face is in front; from below the roles swap.
TEST(FacePairs, CoplanarTouchingFacesOrderBackFacingFirst) {
  const Tri top = tri(0, 0, 1, 0, 0, 1, 0);               // lower block's top, normal +z
  const Tri bottom = tri(0.2, 0.1, 0.2, 1.1, 1.2, 0.1, 0);  // upper block's bottom, normal -z
  const Tri same = tri(0, 0, 0, 1, 1, 0, 0);              // top's twin, reversed: -z
  ViewGeometry below_p = persp({0.3, 0.2, -10}), below_o = ortho();
  below_o.dir = {0, 0, 1};
  for (const ViewGeometry& g : {persp(), ortho()}) {
    ASSERT_EQ(eye_side(g, top.v[0], top.v[1], top.v[2]), 1);
    ASSERT_TRUE(projections_overlap(g, top.v, 3, bottom.v, 3));
    EXPECT_EQ(coplanar_order(g, bottom.v, top.v), -1);
    EXPECT_EQ(coplanar_order(g, top.v, bottom.v), 1);
    EXPECT_EQ(depth_order(g, bottom.v, 3, top.v, 3), -1);
    EXPECT_EQ(depth_order(g, top.v, 3, bottom.v, 3), 1);
    // Coincident triangles (a conforming interface with duplicated nodes).
    EXPECT_EQ(depth_order(g, same.v, 3, top.v, 3), -1);
    EXPECT_EQ(depth_order(g, top.v, 3, same.v, 3), 1);
  }
  for (const ViewGeometry& g : {below_p, below_o}) {
    EXPECT_EQ(depth_order(g, bottom.v, 3, top.v, 3), 1);
    EXPECT_EQ(depth_order(g, top.v, 3, bottom.v, 3), -1);
  }
}

// Coplanar faces facing the same way would belong to overlapping cells: undecided (0), as
// for intersecting faces. A quad works like a triangle.
TEST(FacePairs, CoplanarFacesFacingTheSameWayAreUndecided) {
  const Tri a = tri(0, 0, 1, 0, 0, 1, 0), b = tri(0.2, 0.1, 1.2, 0.1, 0.2, 1.1, 0);
  const Vec3 quad[4] = {{0.5, 0.5, 0}, {0.5, -1, 0}, {-1, -1, 0}, {-1, 0.5, 0}};  // normal -z
  for (const ViewGeometry& g : {persp(), ortho()}) {
    EXPECT_EQ(depth_order(g, a.v, 3, b.v, 3), 0);
    EXPECT_EQ(coplanar_order(g, a.v, b.v), 0);
    EXPECT_EQ(depth_order(g, quad, 4, a.v, 3), -1);
    EXPECT_EQ(depth_order(g, a.v, 3, quad, 4), 1);
  }
  // Seen edge-on there is no order to give.
  ViewGeometry edge_on = ortho();
  edge_on.dir = {1, 0, 0};
  EXPECT_EQ(coplanar_order(edge_on, a.v, quad), 0);
}

// Exactly coplanar after a rotation: coordinates with no short binary form, still one
// plane (z = 3), the tie decided; lifting the upper face by one ulp makes it an ordinary
// pair, decided the same way by the plane test.
TEST(FacePairs, CoplanarRuleIsExactOffTheGrid) {
  const double c = std::cos(0.19198621771937624), s = std::sin(0.19198621771937624);
  auto rot = [&](double x, double y, double z) { return Vec3{c * x - s * y, s * x + c * y, z}; };
  const Vec3 top[3] = {{0, 0, 3}, {1, 0, 3}, {0, 1, 3}};
  Vec3 bottom[3] = {rot(0.1, 0.1, 3), rot(0.1, 0.9, 3), rot(0.9, 0.1, 3)};
  for (const ViewGeometry& g : {persp({0.3, 0.2, 10}), ortho()}) {
    EXPECT_EQ(depth_order(g, bottom, 3, top, 3), -1);
    Vec3 lifted[3] = {bottom[0], bottom[1], bottom[2]};
    for (Vec3& p : lifted) p.z = std::nextafter(3.0, 4.0);
    EXPECT_EQ(depth_order(g, lifted, 3, top, 3), -1);
    for (Vec3& p : lifted) p.z = std::nextafter(3.0, 2.0);  // now intersecting the volume below
    EXPECT_EQ(depth_order(g, lifted, 3, top, 3), 1);
  }
}

// Triangles sharing one vertex and straddling each other's planes take a shortcut (signs at
// the shared vertex, no construction); it must give the clipping path's answer everywhere,
// on a small integer grid (exact collinearities, coplanar points, the eye in a face's plane)
// and off it, in perspective and orthographic views.
TEST(FacePairs, SharedVertexShortcutAgreesWithClipping) {
  std::mt19937 rng(20261204);
  std::uniform_int_distribution<int> grid(-3, 3), eye_xy(-6, 6), eye_z(6, 14), dir_xy(-2, 2);
  std::uniform_real_distribution<double> unit(-3, 3);
  int straddling = 0, outcome[3] = {0, 0, 0};
  for (int trial = 0; trial < 24000; ++trial) {
    const bool on_grid = trial % 3 != 2;
    auto point = [&] {
      return on_grid ? Vec3{double(grid(rng)), double(grid(rng)), double(grid(rng))}
                     : Vec3{unit(rng), unit(rng), unit(rng)};
    };
    const Vec3 p = point();
    Vec3 a[3] = {p, point(), point()}, b[3] = {point(), p, point()};
    if (trial % 2) {
      // A fold seen from above: both planes hold the line through p along x; a's angle at p
      // holds +x, b's holds -x, and the two angles may overlap on either side or not at all.
      std::uniform_real_distribution<double> angle(0.05, 3.0), slope(-2, 2);
      const double k = slope(rng), m = slope(rng);
      auto at = [&](double t, double r, double h) {
        return p + Vec3{r * std::cos(t), r * std::sin(t), h * r * std::sin(t)};
      };
      // Angles of the other vertices: a's at ta and -ua, b's at pi - tb and pi + ub (each
      // angle under pi).
      const double ta = angle(rng), ua = std::min(angle(rng), 3.1 - ta);
      const double tb = angle(rng), ub = std::min(angle(rng), 3.1 - tb);
      a[1] = at(ta, 2, k), a[2] = at(-ua, 2, k);
      b[0] = at(M_PI - tb, 2, m), b[2] = at(M_PI + ub, 2, m);
    }
    std::rotate(a, a + trial % 3, a + 3);
    ViewGeometry g;
    if (trial % 4 == 3) {
      g.ortho = true;
      g.dir = {double(dir_xy(rng)), double(dir_xy(rng)), -1.0 - trial % 2};
    } else {
      g.eye = {double(eye_xy(rng)), double(eye_xy(rng)), double(eye_z(rng))};
      g.dir = {0, 0, -1};
    }
    const int fast = depth_order(g, a, 3, b, 3), slow = depth_order_by_clipping(g, a, 3, b, 3);
    ASSERT_EQ(fast, slow) << "trial " << trial;
    // The shortcut's case: a's two other vertices on opposite sides of b's plane, b's of a's.
    const int ip = static_cast<int>(std::find(a, a + 3, p) - a);
    const bool straddle =
        orient3d(b[0], b[1], b[2], a[(ip + 1) % 3]) * orient3d(b[0], b[1], b[2], a[(ip + 2) % 3]) < 0 &&
        orient3d(a[0], a[1], a[2], b[0]) * orient3d(a[0], a[1], a[2], b[2]) < 0;
    if (straddle) ++straddling, ++outcome[slow + 1];
  }
  // The shortcut's own cases, each answer among them.
  std::printf("straddling pairs %d: A in front %d, undecided %d, B in front %d\n", straddling, outcome[0],
              outcome[1], outcome[2]);
  EXPECT_GT(straddling, 8000);
  EXPECT_GT(outcome[0], 1500);
  EXPECT_GT(outcome[1], 1500);
  EXPECT_GT(outcome[2], 1500);
}
