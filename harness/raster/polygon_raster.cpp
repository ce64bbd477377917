#include "harness/raster/polygon_raster.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include <immintrin.h>

#include "harness/cpu_features.h"
#include "harness/geometry/polygon_plane.h"
#include "harness/geometry/predicates.h"
#include "harness/raster/edge_lanes_avx2.h"
#include "harness/raster/sample_centres.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {

// Sign of det(a, b, c) = (a x b) . c, exact: a double evaluation when it is far from zero
// (bound well above Shewchuk's orient3d error bound), CGAL's exact predicate otherwise.
int facing_sign(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& eye, bool ortho,
                const Vec3& f) {
  const Vec3 a = p1 - p0, b = p2 - p0;
  const Vec3 c = ortho ? f : eye - p0;
  const double det = dot(cross(a, b), c);
  const double perm =
      (std::fabs(a.y * b.z) + std::fabs(a.z * b.y)) * std::fabs(c.x) +
      (std::fabs(a.z * b.x) + std::fabs(a.x * b.z)) * std::fabs(c.y) +
      (std::fabs(a.x * b.y) + std::fabs(a.y * b.x)) * std::fabs(c.z);
  if (std::fabs(det) > 1e-14 * perm) return det > 0 ? 1 : -1;
  return ortho ? orient_direction(p0, p1, p2, f) : orient3d(p0, p1, p2, eye);
}

// Clips a convex polygon in sample space by a*x + b*y + k >= -eta (Sutherland-Hodgman).
int clip_halfplane(const double* px, const double* py, int n, const PolygonRaster::Edge& e,
                   double* ox, double* oy) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const double vi = e.a * px[i] + e.b * py[i] + e.k + e.eta;
    const double vj = e.a * px[j] + e.b * py[j] + e.k + e.eta;
    if (vi >= 0) ox[m] = px[i], oy[m++] = py[i];
    if ((vi >= 0) != (vj >= 0)) {
      const double s = vi / (vi - vj);
      ox[m] = px[i] + s * (px[j] - px[i]);
      oy[m++] = py[i] + s * (py[j] - py[i]);
    }
  }
  return m;
}

// triangle_edges' loop below with the three edges in AVX2 lanes (edge_lanes_avx2.h): the
// same bits, without a jump per edge on the lexicographic order and the ownership (coin
// tosses, mispredicted).
__attribute__((target("avx2"))) void triangle_edges_avx2(const SampleFrame& fr, const Vec3* p, double facing,
                                                         PolygonRaster::Edge* edges) {
  using namespace avx2;
  const EdgeLanes l = edge_lanes(fr, p, facing);
  const __m256d a = dot3(l.mx, l.my, l.mz, fr.affine_dx()), b = dot3(l.mx, l.my, l.mz, fr.affine_dy());
  const __m256d k = add(l.c, dot3(l.mx, l.my, l.mz, fr.affine_origin()));
  const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffff));
  const auto fabs4 = [&](__m256d x) __attribute__((target("avx2"))) { return _mm256_and_pd(x, magnitude); };
  const __m256d m_sum = add(add(fabs4(l.mx), fabs4(l.my)), fabs4(l.mz));
  const __m256d eta = mul(set(1e-12), add(mul(m_sum, set(fr.x_magnitude())), fabs4(l.c)));
  alignas(32) double mx[4], my[4], mz[4], c[4], av[4], bv[4], kv[4], ev[4];
  _mm256_store_pd(mx, l.mx), _mm256_store_pd(my, l.my), _mm256_store_pd(mz, l.mz), _mm256_store_pd(c, l.c);
  _mm256_store_pd(av, a), _mm256_store_pd(bv, b), _mm256_store_pd(kv, k), _mm256_store_pd(ev, eta);
  const int own = owns_zero(fr, l);
  for (int i = 0; i < 3; ++i) {
    PolygonRaster::Edge& e = edges[i];
    e.m = {mx[i], my[i], mz[i]};
    e.c = c[i], e.a = av[i], e.b = bv[i], e.k = kv[i], e.eta = ev[i];
    e.own = (own >> i) & 1;
  }
}

// PolygonRaster::span of four rows, one a lane: the same operations in the same order
// (no multiply-adds: built with -ffp-contract=off, and the target has no FMA), so the same
// columns. An edge's branches on the sign of a are the same for every row.
__attribute__((target("avx2"))) void spans4_avx2(const PolygonRaster::Edge* edges, int sy, int x0, int x1,
                                                 int* lo, int* hi) {
  const __m256d y = _mm256_add_pd(_mm256_set1_pd(sy), _mm256_setr_pd(0.5, 1.5, 2.5, 3.5));
  const __m256d floor_min = _mm256_set1_pd(-1e9), ceil_max = _mm256_set1_pd(1e9);
  __m128i l = _mm_set1_epi32(x0), h = _mm_set1_epi32(x1);
  __m256d reject = _mm256_setzero_pd();
  for (int i = 0; i < 3; ++i) {
    const PolygonRaster::Edge& e = edges[i];
    const __m256d rhs = _mm256_sub_pd(_mm256_set1_pd(-e.eta),
                                      _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(e.b), y), _mm256_set1_pd(e.k)));
    if (e.a == 0) {
      reject = _mm256_or_pd(reject, _mm256_cmp_pd(rhs, _mm256_setzero_pd(), _CMP_GT_OQ));
      continue;
    }
    const __m256d v = _mm256_sub_pd(_mm256_div_pd(rhs, _mm256_set1_pd(e.a)), _mm256_set1_pd(0.5));
    const __m256d number = _mm256_cmp_pd(v, v, _CMP_ORD_Q);  // a NaN row leaves its columns
    const __m256d c = _mm256_min_pd(_mm256_max_pd(v, floor_min), ceil_max);  // floor_to_int's clamp
    if (e.a > 0) {
      const __m256d f = _mm256_blendv_pd(floor_min, _mm256_floor_pd(c), number);
      l = _mm_max_epi32(l, _mm256_cvtpd_epi32(f));
    } else if (e.a < 0) {
      const __m256d f = _mm256_blendv_pd(ceil_max, _mm256_ceil_pd(c), number);
      h = _mm_min_epi32(h, _mm256_cvtpd_epi32(f));
    }
  }
  _mm_storeu_si128(reinterpret_cast<__m128i*>(lo), l);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(hi), h);
  const int rejected = _mm256_movemask_pd(reject);
  for (int j = 0; j < 4; ++j)
    if ((rejected >> j) & 1) lo[j] = INT_MAX, hi[j] = INT_MIN;
}

}  // namespace

// Cheap rejection before the edge planes are built: the polygon's projected bounding box,
// widened far beyond rounding, holds no sample centre. Most exterior faces of a fine mesh
// cover no pixel centre at all, and this test costs a few dot products. Skipped (true)
// when a vertex is not in front of the eye, where the projection says nothing.
bool PolygonRaster::may_cover_a_sample(const SampleFrame& frame, const Vec3* v, int n,
                                       const ProjectedVertex* projected) {
  have_box_ = false;
  double lx = 0, hx = 0, ly = 0, hy = 0;
  for (int i = 0; i < n; ++i) {
    const ProjectedVertex q = projected ? projected[i] : ProjectedVertex::of(frame, v[i]);
    if (!q.in_front) return true;
    const double x = q.x, y = q.y;
    if (i == 0 || x < lx) lx = x;
    if (i == 0 || x > hx) hx = x;
    if (i == 0 || y < ly) ly = y;
    if (i == 0 || y > hy) hy = y;
  }
  SampleRect centres;
  if (!sample_centres_in(frame, lx, hx, ly, hy, centres)) return false;
  // The same box bounds every triangle of the polygon: add_triangle then needs no clipping
  // of the sample grid by the edge half-planes (one extra sample absorbs rounding).
  box_ = SampleRect{floor_to_int(lx - 0.5) - 1, floor_to_int(ly - 0.5) - 1,
                    ceil_to_int(hx - 0.5) + 1, ceil_to_int(hy - 0.5) + 1}
             .intersect(frame.bounds());
  have_box_ = true;
  return true;
}

bool PolygonRaster::setup(const SampleFrame& frame, const Vec3* v, int n,
                          const ProjectedVertex* projected) {
  if (n != 3 && n != 4)
    throw InputError("raster", "polygon", "has " + std::to_string(n) + " vertices, not 3 or 4");
  frame_ = &frame;
  count_ = 0;
  gl_ = frame.rule() == RasterRule::gl;
  plane_ok_ = false;
  if (gl_) {
    if (!setup_gl(frame, v, n, projected)) return false;
    plane_ok_ = set_plane(frame, v, n);  // for plane_depth only
    return true;
  }
  if (!may_cover_a_sample(frame, v, n, projected)) return false;
  if (!set_plane(frame, v, n)) return false;
  plane_ok_ = true;
  if (n == 3) {
    add_triangle(v[0], v[1], v[2]);
  } else {
    int m = 0;
    for (int i = 1; i < 4; ++i)
      if (lex_less(v[i], v[m])) m = i;
    add_triangle(v[m], v[(m + 1) % 4], v[(m + 2) % 4]);
    add_triangle(v[m], v[(m + 2) % 4], v[(m + 3) % 4]);
  }
  return count_ > 0;
}

bool PolygonRaster::set_plane(const SampleFrame& frame, const Vec3* v, int n) {
  return depth_plane(frame, v, n, plane_);
}

bool PolygonRaster::depth_plane(const SampleFrame& frame, const Vec3* v, int n, DepthPlane& out) {
  Plane& plane = out.plane;
  Vec3 on_plane = v[0];
  if (n == 3) {
    plane.n = cross(v[1] - v[0], v[2] - v[0]);
  } else {
    const PolygonPlane p = newell_plane(v, 4);
    plane.n = p.normal;
    on_plane = p.centroid;
  }
  plane.d = -dot(plane.n, on_plane);
  if (frame.ortho()) {
    const double nf = dot(plane.n, frame.forward());
    if (nf == 0) return false;
    out.inv_nf = 1.0 / nf;
  } else {
    out.num = -dot(plane.n, frame.eye() - on_plane);  // no cancellation of large terms
  }
  return true;
}

bool PolygonRaster::triangle_edges(const SampleFrame& fr, const Vec3& p0, const Vec3& p1,
                                   const Vec3& p2, Edge edges[3], bool portable) {
  const bool ortho = fr.ortho();
  const int sigma = facing_sign(p0, p1, p2, fr.eye(), ortho, fr.forward());
  if (sigma == 0) return false;  // edge-on: covers no ray
  // Inside for perspective is det(Pi - e, Pj - e, D) of sign -orient3d(P0, P1, P2, e);
  // for orthographic, ((Pj - Pi) x f) . (Pi - O) has the sign of ((P1-P0) x (P2-P0)) . f.
  const double facing = ortho ? sigma : -sigma;
  const Vec3 p[3] = {p0, p1, p2};
  if (cpu_has_avx2() && !portable) {
    triangle_edges_avx2(fr, p, facing, edges);
    return true;
  }
  const Vec3 dx = fr.affine_dx(), dy = fr.affine_dy(), x0 = fr.affine_origin();
  for (int i = 0; i < 3; ++i) {
    const Vec3 &pi = p[i], &pj = p[(i + 1) % 3];
    const bool fwd = lex_less(pi, pj);
    const Vec3 &pa = fwd ? pi : pj, &pb = fwd ? pj : pi;
    Vec3 m;
    double c = 0;
    if (ortho) {  // E = (pa - O) . ((pb - pa) x f) = c - m' . O
      const Vec3 mp = cross(pb - pa, fr.forward());
      c = dot(mp, pa);
      m = -mp;
    } else {  // E = ((pa - e) x (pb - pa)) . D
      m = cross(pa - fr.eye(), pb - pa);
    }
    const double s = fwd ? facing : -facing;
    Edge& e = edges[i];
    e.m = m * s;
    e.c = c * s;
    e.a = dot(e.m, dx);
    e.b = dot(e.m, dy);
    e.k = e.c + dot(e.m, x0);
    e.eta = 1e-12 * ((std::fabs(e.m.x) + std::fabs(e.m.y) + std::fabs(e.m.z)) * fr.x_magnitude() +
                     std::fabs(e.c));
    // Top-left rule: a zero value counts as inside when moving the sample right (then
    // down) makes it positive. a and b are exact negations across a shared edge.
    e.own = e.a > 0 || (e.a == 0 && (e.b < 0 || (e.b == 0 && dot(e.m, fr.forward()) > 0)));
  }
  return true;
}

bool PolygonRaster::add_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const SampleFrame& fr = *frame_;
  Triangle& t = tri_[count_];
  if (!triangle_edges(fr, p0, p1, p2, t.e)) return false;
  if (have_box_) {  // all vertices in front of the eye: the projected box bounds it
    t.box = box_;
    ++count_;
    return true;
  }
  // Conservative bounds: the grid of sample centres clipped by the three half-planes.
  double bx[2][12], by[2][12];
  const double xl = 0.5, xh = fr.cols() - 0.5, yl = 0.5, yh = fr.rows() - 0.5;
  double* cx = bx[0]; double* cy = by[0];
  cx[0] = xl, cy[0] = yl, cx[1] = xh, cy[1] = yl, cx[2] = xh, cy[2] = yh, cx[3] = xl, cy[3] = yh;
  int n = 4, cur = 0;
  for (int i = 0; i < 3 && n > 0; ++i) {
    n = clip_halfplane(bx[cur], by[cur], n, t.e[i], bx[1 - cur], by[1 - cur]);
    cur = 1 - cur;
  }
  if (n == 0) return false;
  double lx = bx[cur][0], hx = lx, ly = by[cur][0], hy = ly;
  for (int i = 1; i < n; ++i) {
    lx = std::min(lx, bx[cur][i]), hx = std::max(hx, bx[cur][i]);
    ly = std::min(ly, by[cur][i]), hy = std::max(hy, by[cur][i]);
  }
  // Sample sx has its centre at sx + 0.5; one extra sample absorbs rounding of the clip.
  t.box = SampleRect{floor_to_int(lx - 0.5) - 1, floor_to_int(ly - 0.5) - 1,
                     ceil_to_int(hx - 0.5) + 1, ceil_to_int(hy - 0.5) + 1}
              .intersect(fr.bounds());
  if (t.box.empty()) return false;
  ++count_;
  return true;
}

SampleRect PolygonRaster::bounds() const {
  if (count_ == 0) return {};
  SampleRect r = gl_ ? gl_tri_[0].box : tri_[0].box;
  for (int i = 1; i < count_; ++i) {
    const SampleRect& b = gl_ ? gl_tri_[i].box : tri_[i].box;
    r = {std::min(r.x0, b.x0), std::min(r.y0, b.y0), std::max(r.x1, b.x1), std::max(r.y1, b.y1)};
  }
  return r;
}

bool PolygonRaster::span(int i, int sy, int& x0, int& x1) const {
  const double y = sy + 0.5;
  for (const Edge& e : tri_[i].e) {
    const double rhs = -e.eta - (e.b * y + e.k);  // need a * x >= rhs
    if (e.a == 0) {
      if (rhs > 0) return false;
      continue;
    }
    const double v = rhs / e.a - 0.5;  // boundary in sample index units
    if (std::isnan(v)) continue;
    if (e.a > 0)
      x0 = std::max(x0, floor_to_int(v));
    else
      x1 = std::min(x1, ceil_to_int(v));
  }
  return x0 <= x1;
}

void PolygonRaster::spans4(int i, int sy, int x0, int x1, int lo[4], int hi[4], bool portable) const {
  if (cpu_has_avx2() && !portable) {
    spans4_avx2(tri_[i].e, sy, x0, x1, lo, hi);
    return;
  }
  for (int j = 0; j < 4; ++j) {
    lo[j] = x0, hi[j] = x1;
    if (!span(i, sy + j, lo[j], hi[j])) lo[j] = INT_MAX, hi[j] = INT_MIN;
  }
}

}  // namespace vob
