// Cells as the oracle models them (cell_planes.h: the intersection of the outward face
// half-spaces, a non-planar quad taken as its Newell plane), tested for overlap by an exact
// linear program; see "Warped quads" in cell_overlap.h.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include "harness/scene/cell_overlap.h"
#include "harness/scene/cell_overlap_detail.h"
#include "harness/scene/cell_planes.h"

namespace vob {

namespace overlap_detail {

bool has_non_planar_quad(const CellMesh& mesh, int32_t c) { return non_planar_quads(mesh, c) != 0; }

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double norm1(const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }
double norm_inf(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

// The polyhedron's vertices are among the points where three face planes meet. Each such
// point is computed in doubles relative to the cell's first point (`ref`), with a
// first-order bound `err` on its distance (per coordinate) from the exact point of the
// oracle's planes: Cramer's rule y = (c_1 b_i + c_2 b_j + c_3 b_k) / det with c_1 = n_j x n_k
// and so on, b_l = n_l.(o_l - ref); the bound counts the rounding of b, of the cross
// products, of the numerator and of det, and holds while |det| exceeds twice det's own
// error. Then:
//  1. The box, by weak duality: for each axis direction e and each triple, mu = N^-T e
//     (N: the triple's normals), negative entries (rounding, e on a wall between two
//     cones) set to 0, gives e.y = sum mu_l n_l.y + r.y <= sum mu_l b_l + |r|_1 R on the
//     polyhedron, r = e - sum mu_l n_l the residual (bounded with its rounding) and R the
//     largest |y|_inf there, which these six bounds then bound. The normal cones of a
//     bounded polyhedron's vertices cover every direction, so some triple gives each axis
//     a bound; none: the cell is left to the exact LP (not `bounded`, box: the scene).
//  2. A triple whose point certainly lies outside the box (or, when its det is too close
//     to 0 to divide by, farther than |numerator| over |det| + det's error allows) is not
//     a vertex; one that cannot be placed either way makes the cell not `reliable`.
//  3. A point that some face plane has outside by more than its bound is not a vertex;
//     the others are kept. Every true vertex is kept, within its bound; points kept in
//     excess lie at most their bound outside, which only makes the filter cautious.
ModelCell model_cell(const CellMesh& mesh, int32_t c) {
  ModelCell m;
  CellPlanes pl;
  cell_face_planes(mesh, c, pl);
  const int32_t* ids = mesh.cell_points(c);
  const int n = mesh.cell_size(c);
  const int nf = pl.count;
  m.ref = mesh.points[ids[0]];
  double b[6], eb[6], n1[6];
  for (int l = 0; l < nf; ++l) {
    const Vec3 d = pl.o[l] - m.ref;
    b[l] = dot(pl.n[l], d);
    n1[l] = norm1(pl.n[l]);
    eb[l] = 6 * kEps * n1[l] * norm_inf(d);  // b's rounding, o - ref's included
  }
  struct Triple {
    int l[3];
    Vec3 c[3];
    double det, det_err;
    Vec3 num;        // c_1 b_i + c_2 b_j + c_3 b_k
    double num_err;  // its error bound (per coordinate)
    bool placed;     // |det| > 2 det_err: y and err are meaningful
    Vec3 y;
    double err;
  };
  Triple t[20];
  int nt = 0;
  for (int i = 0; i < nf; ++i)
    for (int j = i + 1; j < nf; ++j)
      for (int k = j + 1; k < nf; ++k) {
        Triple& T = t[nt++];
        T.l[0] = i, T.l[1] = j, T.l[2] = k;
        T.c[0] = cross(pl.n[j], pl.n[k]), T.c[1] = cross(pl.n[k], pl.n[i]), T.c[2] = cross(pl.n[i], pl.n[j]);
        T.det = dot(pl.n[i], T.c[0]);
        T.det_err = 8 * kEps * n1[i] * n1[j] * n1[k];
        T.num = Vec3{};
        T.num_err = 0;
        for (int q = 0; q < 3; ++q) {
          const int l = T.l[q];
          const double ce = 4 * kEps * n1[(l == i ? j : i)] * n1[(l == k ? j : k)];  // c_q's rounding
          T.num += T.c[q] * b[l];
          T.num_err += (norm_inf(T.c[q]) + ce) * eb[l] + ce * std::abs(b[l]) +
                       4 * kEps * norm_inf(T.c[q]) * std::abs(b[l]);
        }
        T.placed = std::abs(T.det) > 2 * T.det_err;
        if (!T.placed) continue;
        T.y = T.num / T.det;
        T.err = (T.num_err + norm_inf(T.y) * T.det_err) / (std::abs(T.det) - T.det_err) + kEps * norm_inf(T.y);
        if (!is_finite(T.y) || !std::isfinite(T.err)) T.placed = false;
      }
  // 1. The box: beta[a] + rho[a] R bounds e_a.y, e_a = +-x, +-y, +-z.
  double beta[6], rho[6];
  for (int a = 0; a < 6; ++a) {
    Vec3 e;
    e[a / 2] = a % 2 ? -1.0 : 1.0;
    beta[a] = std::numeric_limits<double>::infinity();
    rho[a] = 0;
    for (int q = 0; q < nt; ++q) {
      const Triple& T = t[q];
      if (!T.placed) continue;
      double mu[3];
      for (int r = 0; r < 3; ++r) mu[r] = dot(T.c[r], e) / T.det;
      const double mu1 = std::abs(mu[0]) + std::abs(mu[1]) + std::abs(mu[2]);
      if (!(std::min({mu[0], mu[1], mu[2]}) >= -1e-6 * mu1)) continue;  // e is not in this cone
      for (double& x : mu) x = std::max(x, 0.0);  // the residual accounts for it
      Vec3 res = e;
      double bound = 0, weight = 0;
      for (int r = 0; r < 3; ++r) {
        const int l = T.l[r];
        res -= pl.n[l] * mu[r];
        bound += mu[r] * (b[l] + eb[l]);
        weight += mu[r] * (n1[l] + std::abs(b[l]) + eb[l]);
      }
      bound += 4 * kEps * weight;
      const double res1 = norm1(res) + 6 * kEps * weight;
      if (!(res1 < 0.25) || !std::isfinite(bound)) continue;
      if (!std::isfinite(beta[a]) || bound + res1 * std::abs(bound) < beta[a] + rho[a] * std::abs(beta[a]))
        beta[a] = bound, rho[a] = res1;
    }
  }
  double beta_max = 0, rho_max = 0;
  for (int a = 0; a < 6; ++a) beta_max = std::max(beta_max, beta[a]), rho_max = std::max(rho_max, rho[a]);
  if (!std::isfinite(beta_max)) {
    m.bounded = m.reliable = false;
    for (int i = 0; i < n; ++i) m.box.add(mesh.points[ids[i]]);
    return m;
  }
  const double R = beta_max / (1 - rho_max) * (1 + 4 * kEps);
  Vec3 lo, hi;  // the polyhedron's box, relative to ref
  for (int a = 0; a < 3; ++a) {
    hi[a] = beta[2 * a] + rho[2 * a] * R;
    lo[a] = -(beta[2 * a + 1] + rho[2 * a + 1] * R);
  }
  // Rounding of ref + y.
  const double pad = 4 * kEps * (norm_inf(m.ref) + R);
  m.box.add(m.ref + lo - Vec3{pad, pad, pad});
  m.box.add(m.ref + hi + Vec3{pad, pad, pad});
  for (int i = 0; i < n; ++i) m.box.add(mesh.points[ids[i]]);
  // 2 and 3.
  for (int q = 0; q < nt; ++q) {
    const Triple& T = t[q];
    if (!T.placed) {
      // |y| >= (|num| - its error) / (|det| + det's error), if the point exists at all.
      const double lower = (norm_inf(T.num) - 2 * T.num_err) / (std::abs(T.det) + T.det_err);
      if (!(lower > R)) m.reliable = false;  // else no point of these planes in the box
      continue;
    }
    bool outside = false;
    for (int a = 0; a < 3; ++a) outside |= T.y[a] - T.err > hi[a] || T.y[a] + T.err < lo[a];
    if (outside) continue;
    bool inside = true;
    for (int l = 0; l < nf && inside; ++l)
      inside = dot(pl.n[l], T.y) - b[l] <= (T.err + 4 * kEps * norm_inf(T.y)) * n1[l] + eb[l];
    if (!inside) continue;
    m.v.push_back(T.y);
    m.err = std::max(m.err, T.err);
  }
  m.reliable = m.reliable && m.v.size() >= 4;
  return m;
}

// A plane of `P` (cell p) keeping every vertex of `Q`'s polyhedron within eps of its outer
// side proves the two overlap by at most max(eps, 0): a cube of half-side t > 0 inside
// both has its corner x + t sign(n) in P and x - t sign(n) in Q, so 2 t ||n||_1 <= eps ||n||_1.
// Returns the smallest such eps over the planes of P (in units of ||n||_1), bounds included.
double thin_by_planes(const CellPlanes& P, const ModelCell& Q) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < P.count; ++i) {
    const Vec3 d = Q.ref - P.o[i];  // rounded; its error joins the bound below
    const double n1 = norm1(P.n[i]);
    double worst = -std::numeric_limits<double>::infinity(), mag = 0;
    for (const Vec3& y : Q.v) {
      worst = std::max(worst, -dot(P.n[i], d + y));
      mag = std::max(mag, norm_inf(d) + norm_inf(y));
    }
    const double eps = worst / n1 + Q.err + 8 * kEps * mag;
    best = std::min(best, eps);
  }
  return best;
}

ModelOverlap model_overlap(const CellMesh& mesh, int32_t a, int32_t b, const ModelCell* ma,
                           const ModelCell* mb, double tol) {
  CellPlanes pa, pb;
  cell_face_planes(mesh, a, pa);
  cell_face_planes(mesh, b, pb);
  ModelOverlap r;
  if (ma && mb && ma->reliable && mb->reliable) {
    const double thin = std::min(thin_by_planes(pa, *mb), thin_by_planes(pb, *ma));
    if (thin <= 0.25 * tol) {
      r.filtered = true;
      r.thickness = std::max(thin, 0.0);  // an upper bound (the argument needs t > 0)
      return r;
    }
  }
  // max t subject to n_i.(x - ref) + t ||n_i||_1 <= n_i.(o_i - ref) for the faces of both,
  // x and t free: t is the half-side of the largest axis-aligned cube inside both cells.
  // All coefficients are exact in CGAL::Gmpzf (products and sums of doubles).
  using ET = CGAL::Gmpzf;
  const Vec3 ref = mesh.points[mesh.cell_points(a)[0]];
  const int m = pa.count + pb.count;
  ET col[4][12], rhs[12];
  for (int i = 0; i < m; ++i) {
    const Vec3& n = i < pa.count ? pa.n[i] : pb.n[i - pa.count];
    const Vec3& o = i < pa.count ? pa.o[i] : pb.o[i - pa.count];
    col[0][i] = ET(n.x), col[1][i] = ET(n.y), col[2][i] = ET(n.z);
    col[3][i] = ET(std::abs(n.x)) + ET(std::abs(n.y)) + ET(std::abs(n.z));
    rhs[i] = ET(n.x) * (ET(o.x) - ET(ref.x)) + ET(n.y) * (ET(o.y) - ET(ref.y)) +
             ET(n.z) * (ET(o.z) - ET(ref.z));
  }
  ET* cols[4] = {col[0], col[1], col[2], col[3]};
  ET obj[4] = {ET(0), ET(0), ET(0), ET(-1)};  // minimise -t
  using Rel = CGAL::Const_oneset_iterator<CGAL::Comparison_result>;
  using Fin = CGAL::Const_oneset_iterator<bool>;
  using Bound = CGAL::Const_oneset_iterator<ET>;
  CGAL::Linear_program_from_iterators<ET**, ET*, Rel, Fin, Bound, Fin, Bound, ET*> lp(
      4, m, cols, rhs, Rel(CGAL::SMALLER), Fin(false), Bound(ET(0)), Fin(false), Bound(ET(0)), obj);
  const CGAL::Quadratic_program_solution<ET> s = CGAL::solve_linear_program(lp, ET());
  r.solved = true;
  if (s.is_unbounded()) {
    r.overlap = true;
    r.thickness = std::numeric_limits<double>::infinity();
    return r;
  }
  // t is free, so the program is feasible; optimal unless unbounded.
  const CGAL::Quotient<ET> minus_t = s.objective_value();
  r.thickness = -2 * CGAL::to_double(minus_t);
  r.overlap = minus_t < CGAL::Quotient<ET>(ET(-0.5 * tol));  // 2 t > tol, exactly
  return r;
}

}  // namespace overlap_detail

QuadWarp worst_quad_warp(const CellMesh& mesh, int32_t c) {
  QuadWarp w;
  if (!overlap_detail::has_non_planar_quad(mesh, c)) return w;
  CellPlanes pl;
  cell_face_planes(mesh, c, pl);
  const int32_t* p = mesh.cell_points(c);
  const LocalFaces& lf = cell_local_faces(mesh.types[c]);
  for (int f = 0; f < lf.count; ++f) {
    if (lf.size[f] != 4) continue;
    double off = 0, size = 0;
    for (int i = 0; i < 4; ++i) {
      const Vec3& x = mesh.points[p[lf.v[f][i]]];
      off = std::max(off, std::abs(dot(pl.n[f], x - pl.o[f])) / length(pl.n[f]));
      for (int j = 0; j < i; ++j) size = std::max(size, length(x - mesh.points[p[lf.v[f][j]]]));
    }
    const double rel = size > 0 ? off / size : 0;
    if (w.face < 0 || rel > w.relative) w.face = f, w.relative = rel;
  }
  return w;
}

ModelOverlap cells_overlap_as_modelled(const CellMesh& mesh, int32_t a, int32_t b, double tol) {
  const overlap_detail::ModelCell ma = overlap_detail::model_cell(mesh, a);
  const overlap_detail::ModelCell mb = overlap_detail::model_cell(mesh, b);
  return overlap_detail::model_overlap(mesh, a, b, &ma, &mb, tol);
}

double model_overlap_tolerance(const CellMesh& mesh) {
  return kOverlapRelative * mesh.bounds().radius();
}

std::string warped_quad_cause(const CellMesh& mesh, int32_t a, int32_t b) {
  const QuadWarp wa = worst_quad_warp(mesh, a), wb = worst_quad_warp(mesh, b);
  if (wa.face < 0 && wb.face < 0) return "";
  const bool first = wa.face >= 0 && (wb.face < 0 || wa.relative >= wb.relative);
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "their quads are not planar (cell %d face %d warped by %.2g of its size) and the "
                "oracle takes each quad as one plane",
                first ? a : b, first ? wa.face : wb.face, first ? wa.relative : wb.relative);
  return buf;
}

}  // namespace vob
