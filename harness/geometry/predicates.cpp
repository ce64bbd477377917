#include "harness/geometry/predicates.h"

#include <algorithm>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace vob {
namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
Epick::Point_3 P(Vec3 v) { return {v.x, v.y, v.z}; }
int to_int(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }

template <class NT>
struct V3 {
  NT x, y, z;
};
template <class NT>
V3<NT> diff(const Vec3& a, const Vec3& o) {  // a - o, each coordinate converted first
  return {NT(a.x) - NT(o.x), NT(a.y) - NT(o.y), NT(a.z) - NT(o.z)};
}
template <class NT>
V3<NT> cross3(const V3<NT>& a, const V3<NT>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class NT>
NT dot3(const V3<NT>& a, const V3<NT>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
// The fan triangles' normals (v[q] - v[0]) x (v[q+1] - v[0]) and their sum, Newell's normal.
template <class NT>
std::vector<V3<NT>> fan_normals(const Vec3* v, size_t n, V3<NT>& sum) {
  std::vector<V3<NT>> t;
  t.reserve(n - 2);
  sum = {NT(0), NT(0), NT(0)};
  V3<NT> a = diff<NT>(v[1], v[0]);
  for (size_t q = 1; q + 1 < n; ++q) {
    const V3<NT> b = diff<NT>(v[q + 1], v[0]);
    t.push_back(cross3(a, b));
    sum = {sum.x + t.back().x, sum.y + t.back().y, sum.z + t.back().z};
    a = b;
  }
  return t;
}
}  // namespace

int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  // CGAL: POSITIVE when det(q-p, r-p, s-p) > 0, our convention exactly (checked in tests).
  return to_int(CGAL::orientation(P(a), P(b), P(c), P(d)));
}

int orient_direction(Vec3 a, Vec3 b, Vec3 c, Vec3 dir) {
  // Differences of doubles are not exact in double; compute them in the lazy exact kernel.
  Epeck::Point_3 pa(a.x, a.y, a.z), pb(b.x, b.y, b.z), pc(c.x, c.y, c.z);
  Epeck::Vector_3 u = pb - pa, v = pc - pa, w(dir.x, dir.y, dir.z);
  return to_int(CGAL::sign(CGAL::determinant(u, v, w)));
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return to_int(CGAL::orientation(Epick::Point_2(ax, ay), Epick::Point_2(bx, by),
                                  Epick::Point_2(cx, cy)));
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) { return CGAL::collinear(P(a), P(b), P(c)); }

bool fan_facings(const Vec3* v, size_t n, int* facing) {
  // Intervals first (certain for all but nearly degenerate fans), rationals where they are not.
  std::vector<size_t> unsure;
  bool zero_unsure = false;
  {
    using I = CGAL::Interval_nt<>;
    V3<I> sum;
    const std::vector<V3<I>> t = fan_normals<I>(v, n, sum);
    const auto certain_zero = [](const I& x) { return x.inf() == 0 && x.sup() == 0; };
    const auto certain_nonzero = [](const I& x) { return x.inf() > 0 || x.sup() < 0; };
    if (certain_zero(sum.x) && certain_zero(sum.y) && certain_zero(sum.z)) {
      std::fill(facing, facing + (n - 2), 0);
      return false;
    }
    zero_unsure = !(certain_nonzero(sum.x) || certain_nonzero(sum.y) || certain_nonzero(sum.z));
    for (size_t q = 0; q < t.size(); ++q) {
      const I d = dot3(t[q], sum);
      if (d.inf() > 0) {
        facing[q] = 1;
      } else if (d.sup() < 0) {
        facing[q] = -1;
      } else if (certain_zero(d)) {
        facing[q] = 0;
      } else {
        unsure.push_back(q);
      }
    }
  }
  if (unsure.empty() && !zero_unsure) return true;
  using Q = CGAL::Exact_rational;
  V3<Q> sum;
  const std::vector<V3<Q>> t = fan_normals<Q>(v, n, sum);
  if (CGAL::is_zero(sum.x) && CGAL::is_zero(sum.y) && CGAL::is_zero(sum.z)) {
    std::fill(facing, facing + (n - 2), 0);
    return false;
  }
  for (const size_t q : unsure) facing[q] = to_int(CGAL::sign(dot3(t[q], sum)));
  return true;
}

}  // namespace vob
