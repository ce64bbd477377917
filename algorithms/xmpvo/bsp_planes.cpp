#include "algorithms/xmpvo/bsp_planes.h"

#include <CGAL/Mpzf.h>
#include <CGAL/determinant.h>

#include <stdexcept>

#include "harness/geometry/predicates.h"

namespace vob::xmpvo::bsp {
namespace {

int sign_of(const CGAL::Mpzf& v) {
  const CGAL::Sign s = v.sign();
  return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0);
}

// A plane exactly: side function n . (x - a).
struct ExactPlane {
  CGAL::Mpzf n[3], a[3];
  explicit ExactPlane(const Vec3* p) {
    const CGAL::Mpzf u[3] = {CGAL::Mpzf(p[1].x) - CGAL::Mpzf(p[0].x), CGAL::Mpzf(p[1].y) - CGAL::Mpzf(p[0].y),
                             CGAL::Mpzf(p[1].z) - CGAL::Mpzf(p[0].z)};
    const CGAL::Mpzf v[3] = {CGAL::Mpzf(p[2].x) - CGAL::Mpzf(p[0].x), CGAL::Mpzf(p[2].y) - CGAL::Mpzf(p[0].y),
                             CGAL::Mpzf(p[2].z) - CGAL::Mpzf(p[0].z)};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    a[0] = CGAL::Mpzf(p[0].x), a[1] = CGAL::Mpzf(p[0].y), a[2] = CGAL::Mpzf(p[0].z);
  }
  CGAL::Mpzf value(Vec3 x) const {
    return n[0] * (CGAL::Mpzf(x.x) - a[0]) + n[1] * (CGAL::Mpzf(x.y) - a[1]) + n[2] * (CGAL::Mpzf(x.z) - a[2]);
  }
  CGAL::Mpzf offset() const { return n[0] * a[0] + n[1] * a[1] + n[2] * a[2]; }  // n . a
};

IA dot(const IA* n, const IA* w) { return n[0] * w[0] + n[1] * w[1] + n[2] * w[2]; }

}  // namespace

RoundUp::RoundUp() : backup_(CGAL::FPU_get_and_set_cw(CGAL_FE_UPWARD)) {}
RoundUp::~RoundUp() { CGAL::FPU_set_cw(backup_); }

int32_t PlaneTable::add(Vec3 a, Vec3 b, Vec3 c) {
  if (added_ >= kMaxTag) throw std::length_error("BSP build: more than 2^30 planes");
  pts_.push_back(a);
  pts_.push_back(b);
  pts_.push_back(c);
  tag_.push_back(added_++);
  const Vec3 du = b - a, dv = c - a;  // round to nearest, before RoundUp
  dbl_.push_back({a, cross(du, dv),
                  {std::fabs(du.y * dv.z) + std::fabs(du.z * dv.y), std::fabs(du.x * dv.z) + std::fabs(du.z * dv.x),
                   std::fabs(du.x * dv.y) + std::fabs(du.y * dv.x)}});
  RoundUp up;
  const IA u[3] = {IA(b.x) - a.x, IA(b.y) - a.y, IA(b.z) - a.z};
  const IA v[3] = {IA(c.x) - a.x, IA(c.y) - a.y, IA(c.z) - a.z};
  IPlane pl;
  pl.n[0] = u[1] * v[2] - u[2] * v[1];
  pl.n[1] = u[2] * v[0] - u[0] * v[2];
  pl.n[2] = u[0] * v[1] - u[1] * v[0];
  const IA ia[3] = {IA(a.x), IA(a.y), IA(a.z)};
  pl.w = dot(pl.n, ia);
  approx_.push_back(pl);
  return size() - 1;
}

int PlaneTable::point_side_exact(int32_t h, Vec3 p) const {
  const Vec3* q = points(h);
  ++exact_points_;
  return orient3d(q[0], q[1], q[2], p);
}

IBox PlaneTable::edge_point(Vec3 p, Vec3 q, int32_t j) const {
  const IPlane& h = approx_[j];
  const Vec3 a = points(j)[0];
  const IA wp[3] = {IA(p.x) - a.x, IA(p.y) - a.y, IA(p.z) - a.z};
  const IA wq[3] = {IA(q.x) - a.x, IA(q.y) - a.y, IA(q.z) - a.z};
  const IA dp = dot(h.n, wp), dq = dot(h.n, wq);
  const IA t = dp / (dp - dq);  // the whole line when dp - dq is not known nonzero
  return {IA(p.x) + (IA(q.x) - p.x) * t, IA(p.y) + (IA(q.y) - p.y) * t, IA(p.z) + (IA(q.z) - p.z) * t};
}

IBox PlaneTable::meet_point(int32_t t, int32_t i, int32_t j) const {
  // Relative to a point o of plane t: y = x - o solves n_t.y = 0, n_i.y = ri, n_j.y = rj,
  // so y = (ri (n_j x n_t) + rj (n_t x n_i)) / det(n_t, n_i, n_j).
  const Vec3 o = points(t)[0], ai = points(i)[0], aj = points(j)[0];
  const IA* nt = approx_[t].n;
  const IA* ni = approx_[i].n;
  const IA* nj = approx_[j].n;
  const IA di[3] = {IA(ai.x) - o.x, IA(ai.y) - o.y, IA(ai.z) - o.z};
  const IA dj[3] = {IA(aj.x) - o.x, IA(aj.y) - o.y, IA(aj.z) - o.z};
  const IA ri = dot(ni, di), rj = dot(nj, dj);
  const IA jt[3] = {nj[1] * nt[2] - nj[2] * nt[1], nj[2] * nt[0] - nj[0] * nt[2], nj[0] * nt[1] - nj[1] * nt[0]};
  const IA ti[3] = {nt[1] * ni[2] - nt[2] * ni[1], nt[2] * ni[0] - nt[0] * ni[2], nt[0] * ni[1] - nt[1] * ni[0]};
  const IA det = dot(nj, ti);  // n_t . (n_i x n_j) = n_j . (n_t x n_i)
  return {IA(o.x) + (ri * jt[0] + rj * ti[0]) / det, IA(o.y) + (ri * jt[1] + rj * ti[1]) / det,
          IA(o.z) + (ri * jt[2] + rj * ti[2]) / det};
}

int PlaneTable::filtered_side(int32_t h, const IBox& b) const {
  const Vec3 a = points(h)[0];
  const IA w[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
  const IA v = dot(approx_[h].n, w);
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  return 2;
}

int PlaneTable::exact_side_edge(Vec3 p, Vec3 q, int32_t j, int32_t h) const {
  // x = (dp q - dq p) / (dp - dq) with d the side function of j; h's side function f is
  // affine, so f(x) = (dp f(q) - dq f(p)) / (dp - dq).
  const ExactPlane pj(points(j)), ph(points(h));
  const CGAL::Mpzf dp = pj.value(p), dq = pj.value(q);
  return sign_of(dp * ph.value(q) - dq * ph.value(p)) * sign_of(dp - dq);
}

int PlaneTable::exact_side_meet(int32_t t, int32_t i, int32_t j, int32_t h) const {
  // With rows (n, -n.a) per plane, M (x, 1) = (0, 0, 0, f_h(x)); by Cramer's rule on the
  // last unknown, f_h(x) = det(M) / det(n_t, n_i, n_j).
  const ExactPlane e[4] = {ExactPlane(points(t)), ExactPlane(points(i)), ExactPlane(points(j)), ExactPlane(points(h))};
  CGAL::Mpzf w[4];
  for (int k = 0; k < 4; ++k) w[k] = -e[k].offset();
  const CGAL::Mpzf d4 = CGAL::determinant(e[0].n[0], e[0].n[1], e[0].n[2], w[0], e[1].n[0], e[1].n[1], e[1].n[2], w[1],
                                          e[2].n[0], e[2].n[1], e[2].n[2], w[2], e[3].n[0], e[3].n[1], e[3].n[2], w[3]);
  const CGAL::Mpzf d3 = CGAL::determinant(e[0].n[0], e[0].n[1], e[0].n[2], e[1].n[0], e[1].n[1], e[1].n[2], e[2].n[0],
                                          e[2].n[1], e[2].n[2]);
  return sign_of(d4) * sign_of(d3);
}

}  // namespace vob::xmpvo::bsp
