#include "algorithms/xmpvo/face_pairs.h"

#include <cmath>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include "algorithms/xmpvo/bounded_double.h"
#include "harness/geometry/predicates.h"

namespace vob::xmpvo {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EPoint = EK::Point_3;

int sign_of(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

// D(x, y, z) of face_pairs.h in any number type; differences are taken in NT so that the
// interval and rational evaluations bound resp. equal the exact value.
template <class NT>
NT det3(const NT u[3], const NT v[3], const NT w[3]) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

template <class NT>
NT det_d(const ViewGeometry& g, Vec3 x, Vec3 y, Vec3 z) {
  if (g.ortho) {
    const NT d[3] = {NT(g.dir.x), NT(g.dir.y), NT(g.dir.z)};
    const NT u[3] = {NT(y.x) - NT(x.x), NT(y.y) - NT(x.y), NT(y.z) - NT(x.z)};
    const NT v[3] = {NT(z.x) - NT(x.x), NT(z.y) - NT(x.y), NT(z.z) - NT(x.z)};
    return det3(d, u, v);
  }
  const Vec3 e = g.eye;
  const NT u[3] = {NT(x.x) - NT(e.x), NT(x.y) - NT(e.y), NT(x.z) - NT(e.z)};
  const NT v[3] = {NT(y.x) - NT(e.x), NT(y.y) - NT(e.y), NT(y.z) - NT(e.z)};
  const NT w[3] = {NT(z.x) - NT(e.x), NT(z.y) - NT(e.y), NT(z.z) - NT(e.z)};
  return det3(u, v, w);
}

// O(a) D(b,p,q) - O(b) D(a,p,q) with O(x) = D(c,d,x); its sign times sign(O(a)) is
// crossing_side (D is affine in its first argument; see the header).
template <class NT>
NT crossing_value(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q,
                  NT& oa) {
  oa = det_d<NT>(g, c, d, a);
  const NT ob = det_d<NT>(g, c, d, b);
  return oa * det_d<NT>(g, b, p, q) - ob * det_d<NT>(g, a, p, q);
}

int crossing_exact(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q) {
  {
    Fd oa;
    const Fd v = crossing_value<Fd>(g, a, b, c, d, p, q, oa);
    const int sv = fd_sign(v), so = fd_sign(oa);
    if (sv != 2 && so != 2) return sv * so;
  }
  {
    // Interval filter first; rationals only when the interval straddles zero.
    CGAL::Protect_FPU_rounding<true> guard;
    using I = CGAL::Interval_nt_advanced;
    I oa;
    const I v = crossing_value<I>(g, a, b, c, d, p, q, oa);
    const CGAL::Uncertain<CGAL::Sign> sv = CGAL::sign(v), so = CGAL::sign(oa);
    if (CGAL::is_certain(sv) && CGAL::is_certain(so))
      return sign_of(sv.make_certain()) * sign_of(so.make_certain());
  }
  using Q = CGAL::Exact_rational;
  Q oa;
  const Q v = crossing_value<Q>(g, a, b, c, d, p, q, oa);
  return sign_of(CGAL::sign(v)) * sign_of(CGAL::sign(oa));
}

// ---- Generic convex-polygon overlap on any point type, given an exact side function ----

// Orientation of a convex polygon's projection: the first non-zero side of a fan triangle.
template <class P, class Side>
int polygon_orientation(const P* a, int n, Side side) {
  for (int i = 1; i + 1 < n; ++i)
    if (int s = side(a[0], a[i], a[i + 1])) return s;
  return 0;
}

// True when an edge line of A has all of B on its closed outer side. An edge whose line
// has no vertex of A strictly inside (zero length, or seen end-on) separates nothing.
template <class P, class Side>
bool separates(const P* a, int na, int sa, const P* b, int nb, Side side, bool check_edges) {
  for (int i = 0; i < na; ++i) {
    const P& p = a[i];
    const P& q = a[(i + 1) % na];
    if (check_edges) {
      bool proper = false;
      // Skip the edge's own endpoints: exactly zero, the costliest case for lazy exact points.
      for (int k = 2; k < na && !proper; ++k) proper = side(p, q, a[(i + k) % na]) == sa;
      if (!proper) continue;
    }
    bool all_out = true;
    for (int j = 0; j < nb && all_out; ++j) all_out = side(p, q, b[j]) * sa <= 0;
    if (all_out) return true;
  }
  return false;
}

template <class P, class Side>
bool overlap_generic(const P* a, int na, const P* b, int nb, Side side, bool check_edges) {
  const int sa = polygon_orientation(a, na, side), sb = polygon_orientation(b, nb, side);
  if (sa == 0 || sb == 0) return false;  // no open projection
  return !separates(a, na, sa, b, nb, side, check_edges) &&
         !separates(b, nb, sb, a, na, side, check_edges);
}

// Exact side on constructed (rational) points, same convention as edge_side.
struct ExactSide {
  const ViewGeometry* g;
  EPoint eye;
  EK::Vector_3 dir;
  explicit ExactSide(const ViewGeometry& view)
      : g(&view), eye(view.eye.x, view.eye.y, view.eye.z), dir(view.dir.x, view.dir.y, view.dir.z) {}
  int operator()(const EPoint& a, const EPoint& b, const EPoint& p) const {
    if (g->ortho) return sign_of(CGAL::sign(CGAL::determinant(b - a, p - a, dir)));
    return sign_of(CGAL::orientation(eye, a, b, p));
  }
};

// The part of polygon `a` on the closed side `keep` (+1 / -1) of `plane`
// (Sutherland-Hodgman, exact).
std::vector<EPoint> clip(const std::vector<EPoint>& a, const EK::Plane_3& plane, int keep) {
  std::vector<EPoint> out;
  const size_t n = a.size();
  auto value = [&](const EPoint& p) {
    return plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d();
  };
  for (size_t i = 0; i < n; ++i) {
    const EPoint& p = a[i];
    const EPoint& q = a[(i + 1) % n];
    const EK::FT vp = value(p), vq = value(q);
    const int sp = sign_of(CGAL::sign(vp)) * keep, sq = sign_of(CGAL::sign(vq)) * keep;
    if (sp >= 0) out.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push_back(p + (q - p) * (vp / (vp - vq)));
  }
  return out;
}

std::vector<EPoint> to_exact(const Vec3* a, int n) {
  std::vector<EPoint> out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) out.emplace_back(a[i].x, a[i].y, a[i].z);
  return out;
}

// Sides of B's vertices relative to A's plane, in units of "towards the eye": +1 when
// every vertex is on the eye's closed side (and not all on the plane), -1 on the far
// closed side, 0 when B straddles the plane, kCoplanar when every vertex lies in it.
constexpr int kCoplanar = 2;
int plane_side_of(const ViewGeometry& g, const Vec3* a, const Vec3* b, int nb) {
  const int near = eye_side(g, a[0], a[1], a[2]);
  if (near == 0) return 0;
  bool any_near = false, any_far = false;
  for (int j = 0; j < nb; ++j) {
    // A shared vertex is on the plane: exactly zero, and costly for the filtered predicate.
    if (b[j] == a[0] || b[j] == a[1] || b[j] == a[2]) continue;
    const int s = orient3d(a[0], a[1], a[2], b[j]) * near;
    any_near |= s > 0;
    any_far |= s < 0;
  }
  if (!any_near && !any_far) return kCoplanar;
  if (any_near == any_far) return 0;  // straddles
  return any_near ? 1 : -1;
}

// Along the ray through X = Xh / w (w = 1 for a point; w = O(a) - O(b), Xh = O(a) b - O(b) a
// for the crossing of (a, b) with the projected line of (c, d)), the ray parameter of the
// plane of face F is num / den; returns num_A den_B - num_B den_A and den_A, den_B.
template <class NT>
struct RayPoint {
  NT w, h[3];
};
template <class NT>
RayPoint<NT> ray_point(const ViewGeometry& g, const Vec3* crossing, Vec3 p) {
  RayPoint<NT> r;
  if (!crossing) {
    r.w = NT(1);
    r.h[0] = NT(p.x), r.h[1] = NT(p.y), r.h[2] = NT(p.z);
    return r;
  }
  const Vec3 a = crossing[0], b = crossing[1], c = crossing[2], d = crossing[3];
  const NT oa = det_d<NT>(g, c, d, a), ob = det_d<NT>(g, c, d, b);
  r.w = oa - ob;
  for (int i = 0; i < 3; ++i) r.h[i] = oa * NT(b[i]) - ob * NT(a[i]);
  return r;
}
template <class NT>
void plane_param(const ViewGeometry& g, const Vec3* f, const RayPoint<NT>& x, NT& num, NT& den) {
  NT u[3], v[3], n[3];
  for (int i = 0; i < 3; ++i) u[i] = NT(f[1][i]) - NT(f[0][i]), v[i] = NT(f[2][i]) - NT(f[0][i]);
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  if (g.ortho) {
    // X + t dir on the plane: t = n.(f0 w - Xh) / (w n.dir).
    num = NT(0), den = NT(0);
    for (int i = 0; i < 3; ++i) {
      num = num + n[i] * (NT(f[0][i]) * x.w - x.h[i]);
      den = den + n[i] * NT(g.dir[i]);
    }
    den = den * x.w;
  } else {
    // e + t (X - e) on the plane: t = w n.(f0 - e) / n.(Xh - w e).
    num = NT(0), den = NT(0);
    for (int i = 0; i < 3; ++i) {
      num = num + n[i] * (NT(f[0][i]) - NT(g.eye[i]));
      den = den + n[i] * (x.h[i] - x.w * NT(g.eye[i]));
    }
    num = num * x.w;
  }
}
// sign(t_A - t_B) as (value, den_A, den_B) signs.
template <class NT>
void plane_order_value(const ViewGeometry& g, const Vec3* a, const Vec3* b, const Vec3* crossing,
                       Vec3 p, NT& value, NT& den_a, NT& den_b) {
  const RayPoint<NT> x = ray_point<NT>(g, crossing, p);
  NT num_a, num_b;
  plane_param(g, a, x, num_a, den_a);
  plane_param(g, b, x, num_b, den_b);
  value = num_a * den_b - num_b * den_a;
}

int plane_order_exact(const ViewGeometry& g, const Vec3* a, const Vec3* b, const Vec3* crossing, Vec3 p) {
  {
    Fd v, da, db;
    plane_order_value<Fd>(g, a, b, crossing, p, v, da, db);
    const int sv = fd_sign(v), sa = fd_sign(da), sb = fd_sign(db);
    if (sv != 2 && sa != 2 && sb != 2) return sv * sa * sb;
  }
  {
    CGAL::Protect_FPU_rounding<true> guard;
    using I = CGAL::Interval_nt_advanced;
    I v, da, db;
    plane_order_value<I>(g, a, b, crossing, p, v, da, db);
    const auto sv = CGAL::sign(v), sa = CGAL::sign(da), sb = CGAL::sign(db);
    if (CGAL::is_certain(sv) && CGAL::is_certain(sa) && CGAL::is_certain(sb))
      return sign_of(sv.make_certain()) * sign_of(sa.make_certain()) * sign_of(sb.make_certain());
  }
  using Q = CGAL::Exact_rational;
  Q v, da, db;
  plane_order_value<Q>(g, a, b, crossing, p, v, da, db);
  return sign_of(CGAL::sign(v)) * sign_of(CGAL::sign(da)) * sign_of(CGAL::sign(db));
}

Fd fd(const double x[2]) { return {x[0], x[1]}; }
void store(Fd x, double out[2]) { out[0] = x.v, out[1] = x.e; }

}  // namespace

VertexRay VertexRay::at_point(const ViewGeometry& g, Vec3 p) {
  VertexRay r;
  r.g = g;
  r.p[0] = p;
  for (int i = 0; i < 3; ++i) r.h[i][0] = p[i], r.h[i][1] = 0;
  return r;
}

VertexRay VertexRay::at_crossing(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  VertexRay r;
  r.g = g;
  r.crossing = true;
  r.p[0] = a, r.p[1] = b, r.p[2] = c, r.p[3] = d;
  // ray_point's arithmetic, its two determinants kept for oa and ob.
  const Fd oa = det_d<Fd>(g, c, d, a), ob = det_d<Fd>(g, c, d, b);
  store(oa, r.oa);
  store(ob, r.ob);
  store(oa - ob, r.w);
  for (int i = 0; i < 3; ++i) store(oa * Fd(b[i]) - ob * Fd(a[i]), r.h[i]);
  return r;
}

FacePlane FacePlane::of(const Vec3* face) {
  FacePlane pl;
  Fd u[3], v[3];
  for (int i = 0; i < 3; ++i) {
    pl.f[i] = face[i];
    u[i] = Fd(face[1][i]) - Fd(face[0][i]);
    v[i] = Fd(face[2][i]) - Fd(face[0][i]);
  }
  store(u[1] * v[2] - u[2] * v[1], pl.n[0]);
  store(u[2] * v[0] - u[0] * v[2], pl.n[1]);
  store(u[0] * v[1] - u[1] * v[0], pl.n[2]);
  return pl;
}

int vertex_side(const VertexRay& r, Vec3 p, Vec3 q) {
  if (!r.crossing) return edge_side(r.g, r.p[0], p, q);
  const Fd oa = fd(r.oa), ob = fd(r.ob);
  const Fd v = oa * det_d<Fd>(r.g, r.p[1], p, q) - ob * det_d<Fd>(r.g, r.p[0], p, q);
  const int sv = fd_sign(v), so = fd_sign(oa);
  if (sv != 2 && so != 2) return sv * so;
  return crossing_exact(r.g, r.p[0], r.p[1], r.p[2], r.p[3], p, q);
}

int vertex_plane_order(const VertexRay& r, const FacePlane& a, const FacePlane& b) {
  // plane_param with the cached normals and ray point.
  auto param = [&r](const FacePlane& f, Fd& num, Fd& den) {
    const Fd w = fd(r.w);
    num = Fd(0), den = Fd(0);
    for (int i = 0; i < 3; ++i) {
      const Fd n = fd(f.n[i]), h = fd(r.h[i]);
      if (r.g.ortho) {
        num = num + n * (Fd(f.f[0][i]) * w - h);
        den = den + n * Fd(r.g.dir[i]);
      } else {
        num = num + n * (Fd(f.f[0][i]) - Fd(r.g.eye[i]));
        den = den + n * (h - w * Fd(r.g.eye[i]));
      }
    }
    if (r.g.ortho) den = den * w;
    else num = num * w;
  };
  Fd na, da, nb, db;
  param(a, na, da);
  param(b, nb, db);
  const int sv = fd_sign(na * db - nb * da), sa = fd_sign(da), sb = fd_sign(db);
  if (sv != 2 && sa != 2 && sb != 2) return sv * sa * sb;
  return plane_order_exact(r.g, a.f, b.f, r.crossing ? r.p : nullptr, r.p[0]);
}

int plane_order_at(const ViewGeometry& g, const Vec3* a, const Vec3* b, Vec3 p) {
  return plane_order_exact(g, a, b, nullptr, p);
}

int plane_order_at_crossing(const ViewGeometry& g, const Vec3* a, const Vec3* b, Vec3 c0, Vec3 c1,
                            Vec3 d0, Vec3 d1) {
  const Vec3 crossing[4] = {c0, c1, d0, d1};
  return plane_order_exact(g, a, b, crossing, Vec3{});
}

ViewGeometry ViewGeometry::of(const Camera& view) {
  ViewGeometry g;
  g.ortho = view.ortho;
  g.eye = view.eye;
  g.dir = view.forward();
  return g;
}

int edge_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 p) {
  if (p == a || p == b || a == b) return 0;  // shared vertices: skip the exact fallback
  // Orthographic: the eye at infinity along -dir turns orient3d(eye, a, b, p) into
  // sign(det(dir, b-a, p-a)).
  return g.ortho ? orient_direction(a, b, p, g.dir) : orient3d(g.eye, a, b, p);
}

int eye_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c) {
  return g.ortho ? -orient_direction(a, b, c, g.dir) : orient3d(a, b, c, g.eye);
}

int crossing_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q) {
  return crossing_exact(g, a, b, c, d, p, q);
}

int edge_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 p) {
  const double v = det_d<double>(g, a, b, p);
  return (v > 0) - (v < 0);
}

int eye_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const double v = g.ortho ? -dot(n, g.dir) : dot(n, g.eye - a);
  return (v > 0) - (v < 0);
}

int crossing_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q) {
  double oa;
  const double v = crossing_value<double>(g, a, b, c, d, p, q, oa);
  return ((v > 0) - (v < 0)) * ((oa > 0) - (oa < 0));
}

bool projections_overlap(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb) {
  auto side = [&g](Vec3 x, Vec3 y, Vec3 z) { return edge_side(g, x, y, z); };
  // Triangles need no edge check: a non-zero orientation makes every edge proper.
  return overlap_generic(a, na, b, nb, side, na > 3 || nb > 3);
}

int coplanar_order(const ViewGeometry& g, const Vec3* a, const Vec3* b) {
  const int fa = eye_side(g, a[0], a[1], a[2]), fb = eye_side(g, b[0], b[1], b[2]);
  if (fa == 0 || fa == fb) return 0;  // edge-on, or both cells on one side: they overlap
  return fa < 0 ? -1 : 1;
}

namespace {

// The straddling case by construction: split A by B's plane. Along a ray through the
// overlap, A's point on the eye's side of B's plane means A is in front. The part of A on
// the near side overlapping B decides; both parts overlapping B means the faces intersect.
int straddling_order_by_clipping(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb) {
  const int near_b = eye_side(g, b[0], b[1], b[2]);
  if (near_b == 0) return 0;
  const EK::Plane_3 plane_b(EPoint(b[0].x, b[0].y, b[0].z), EPoint(b[1].x, b[1].y, b[1].z),
                            EPoint(b[2].x, b[2].y, b[2].z));
  const std::vector<EPoint> ea = to_exact(a, na), eb = to_exact(b, nb);
  const std::vector<EPoint> a_near = clip(ea, plane_b, near_b), a_far = clip(ea, plane_b, -near_b);
  const ExactSide side(g);
  const bool near_overlaps = a_near.size() >= 3 &&
                             overlap_generic(a_near.data(), static_cast<int>(a_near.size()),
                                             eb.data(), nb, side, true);
  const bool far_overlaps = a_far.size() >= 3 &&
                            overlap_generic(a_far.data(), static_cast<int>(a_far.size()),
                                            eb.data(), nb, side, true);
  if (near_overlaps == far_overlaps) return 0;  // intersecting, coplanar, or no overlap
  return near_overlaps ? -1 : 1;
}

constexpr int kNotShared = 3;

// Triangles A and B sharing exactly one vertex p, each straddling the other's plane. The
// planes meet in a line L through p; its projection L' splits the image into the half
// where A's plane is nearer (H_A: there lie the projections of A's points on the eye's side
// of B's plane and of B's points beyond A's plane) and the half where B's is. A meets L in
// a segment from p, B too. If both segments leave p the same way, the faces share it: they
// intersect. Otherwise the overlap of the projections is a convex set that can meet L'
// only at p, so it lies in one half, and near p it is the overlap of the two triangles'
// projected angles at p. In each half each angle is bounded by one of its triangle's edges
// from p (that triangle's neighbour of p there) and by L'. So, in H_A, with alpha_near the
// neighbour of p in A on the eye's side of B's plane and beta_far B's neighbour beyond A's
// plane: the angles overlap there iff beta_far lies strictly inside A's angle and
// alpha_near strictly inside B's; if exactly one of the two holds, both angles hold the
// same end of L' (the segments leave p the same way). Likewise in H_B. Only orientation
// signs of input points: no construction (the clipping path builds lazy exact points whose
// every predicate is exactly degenerate at p, so each call ran the rational arithmetic).
// Returns kNotShared when A and B do not share exactly one vertex.
int shared_vertex_order(const ViewGeometry& g, const Vec3* a, const Vec3* b) {
  int ia = -1, jb = -1, shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[i] == b[j]) ia = i, jb = j, ++shared;
  if (shared != 1) return kNotShared;
  const int eye_a = eye_side(g, a[0], a[1], a[2]), eye_b = eye_side(g, b[0], b[1], b[2]);
  if (eye_a == 0 || eye_b == 0) return 0;  // seen edge-on: no open projection
  const Vec3 p = a[ia];
  const Vec3 a1 = a[(ia + 1) % 3], a2 = a[(ia + 2) % 3], b1 = b[(jb + 1) % 3], b2 = b[(jb + 2) % 3];
  // Sides of the other plane, positive towards the eye; a straddling triangle has its two
  // other vertices strictly on opposite sides.
  const int sa1 = orient3d(b[0], b[1], b[2], a1) * eye_b, sa2 = orient3d(b[0], b[1], b[2], a2) * eye_b;
  const int sb1 = orient3d(a[0], a[1], a[2], b1) * eye_a, sb2 = orient3d(a[0], a[1], a[2], b2) * eye_a;
  if (sa1 * sa2 >= 0 || sb1 * sb2 >= 0) return kNotShared;
  const Vec3 alpha_near = sa1 > 0 ? a1 : a2, alpha_far = sa1 > 0 ? a2 : a1;
  const Vec3 beta_near = sb1 > 0 ? b1 : b2, beta_far = sb1 > 0 ? b2 : b1;
  // x strictly inside the projected angle at p between the rays to u and v.
  auto inside = [&](Vec3 x, Vec3 u, Vec3 v) {
    const int su = edge_side(g, p, u, v);
    return su != 0 && edge_side(g, p, u, x) == su && edge_side(g, p, v, x) == -su;
  };
  const bool c1 = inside(beta_far, alpha_near, alpha_far), c2 = inside(alpha_near, beta_near, beta_far);
  const bool c3 = inside(beta_near, alpha_near, alpha_far), c4 = inside(alpha_far, beta_near, beta_far);
  if (c1 != c2 || c3 != c4) return 0;  // both segments leave p the same way: they intersect
  const bool near_overlaps = c1, far_overlaps = c3;  // in H_A, in H_B
  if (near_overlaps == far_overlaps) return 0;
  return near_overlaps ? -1 : 1;
}

int depth_order_impl(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb, bool shortcut) {
  // B entirely on the far (near) closed side of A's plane: A (B) is in front wherever they
  // overlap, because every ray meets A's plane once and the eye is on the near side.
  const int b_side = plane_side_of(g, a, b, nb);
  if (b_side == kCoplanar) return coplanar_order(g, a, b);
  if (b_side != 0) return b_side > 0 ? 1 : -1;
  if (int s = plane_side_of(g, b, a, na)) return s > 0 ? -1 : 1;
  // Each straddles the other's plane.
  if (shortcut && na == 3 && nb == 3) {
    const int r = shared_vertex_order(g, a, b);
    if (r != kNotShared) return r;
  }
  return straddling_order_by_clipping(g, a, na, b, nb);
}

}  // namespace

int depth_order(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb) {
  return depth_order_impl(g, a, na, b, nb, true);
}

int depth_order_by_clipping(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb) {
  return depth_order_impl(g, a, na, b, nb, false);
}

}  // namespace vob::xmpvo
