// A double with a running bound on its rounding error (inputs exact): a value larger than
// twice its bound has a certain sign. XMPVO's semi-static filter (face_pairs.cpp, plane
// keys, the edge sweep's plane sides): far cheaper than switching the rounding mode, and
// tight where the inputs are close together (mesh coordinates far from the origin), unlike
// a bound proportional to the summands' magnitudes.
#pragma once
#include <cmath>

namespace vob::xmpvo {

struct Fd {
  double v = 0, e = 0;
  Fd() = default;
  explicit Fd(double x) : v(x), e(0) {}
  Fd(double v_, double e_) : v(v_), e(e_) {}
};
constexpr double kFdU = 0x1p-52;  // twice the unit roundoff: also covers rounding of e
inline Fd operator+(Fd a, Fd b) {
  const double v = a.v + b.v;
  return {v, a.e + b.e + kFdU * std::fabs(v)};
}
inline Fd operator-(Fd a, Fd b) {
  const double v = a.v - b.v;
  return {v, a.e + b.e + kFdU * std::fabs(v)};
}
inline Fd operator*(Fd a, Fd b) {
  const double v = a.v * b.v;
  return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kFdU * std::fabs(v)};
}
// +1 / -1 when certain, 2 when not (also on overflow, NaN or underflow-sized values).
inline int fd_sign(Fd x) {
  if (!(std::fabs(x.v) < 1e280) || !(x.e < 1e280)) return 2;
  const double bound = 2 * x.e + 1e-290;
  if (x.v > bound) return 1;
  if (x.v < -bound) return -1;
  return 2;
}

}  // namespace vob::xmpvo
