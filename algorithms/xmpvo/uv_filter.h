// XMPVO's floating-point sign filter on the projected doubles, so that exact predicates
// run only where the double answer is too close to call.
//
// For a point x in front of the eye (z > 0), the sign of D(x, p, q) (face_pairs.h) is
// sign_n * orient2d(uv_x, uv_p, uv_q), sign_n the sign of det(right, up, forward): D is a
// determinant of the rays, and the projected coordinates are the rays in that basis divided
// by positive depths. Each projected double lies within `slack` of its exact projection
// (Projection::run checks a rounding bound for every point of the view and turns the
// filter off when one exceeds slack / 8), an arrangement vertex within its box. When
// |orient2d| exceeds what moving every point within those bounds can change, the sign is
// certain; otherwise uv_side returns 2 and the caller asks the exact predicate.
#pragma once
#include <cmath>
#include <utility>

namespace vob::xmpvo {

using Uv = std::pair<double, double>;

// Sign of orient2d(p, q, x) for x within (rx, ry) of (xx, xy), p and q within s of theirs:
// +1 / -1 when certain, 0 when not (no branch: for loops whose outcomes are unpredictable).
inline int uv_sign(double xx, double xy, double rx, double ry, Uv p, Uv q, double s) {
  const double ax = q.first - p.first, ay = q.second - p.second;
  const double bx = xx - p.first, by = xy - p.second;
  const double o = ax * by - ay * bx;
  const double ea = 2 * s, ex = rx + s, ey = ry + s;
  // First-order and product terms of the perturbation, then the rounding of o itself.
  const double bound = std::fabs(ax) * ey + std::fabs(by) * ea + std::fabs(ay) * ex +
                       std::fabs(bx) * ea + ea * (ex + ey) +
                       1e-15 * (std::fabs(ax * by) + std::fabs(ay * bx));
  return (o > 1.001 * bound) - (o < -1.001 * bound);
}

// The same, 2 when not certain.
inline int uv_side(double xx, double xy, double rx, double ry, Uv p, Uv q, double s) {
  const int sign = uv_sign(xx, xy, rx, ry, p, q, s);
  return sign != 0 ? sign : 2;
}

// The same for x itself a projected point (within s).
inline int uv_sign(Uv x, Uv p, Uv q, double s) { return uv_sign(x.first, x.second, s, s, p, q, s); }
inline int uv_side(Uv x, Uv p, Uv q, double s) { return uv_side(x.first, x.second, s, s, p, q, s); }

}  // namespace vob::xmpvo
