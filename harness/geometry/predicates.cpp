#include "harness/geometry/predicates.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace vob {
namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
Epick::Point_3 P(Vec3 v) { return {v.x, v.y, v.z}; }
int to_int(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }
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

}  // namespace vob
