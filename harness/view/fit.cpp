#include "harness/view/fit.h"

#include <algorithm>
#include <cmath>

#include "harness/scene/input_error.h"

namespace vob {

Camera fit_window_to_box(const Camera& c, const Aabb& box, int64_t pixels) {
  constexpr int kMaxSide = 16384;
  if (pixels < 1 || pixels > int64_t(kMaxSide) * kMaxSide)
    throw InputError("camera", "fit", std::to_string(pixels) + " pixels is not within 1..16384^2");
  const Vec3 f = c.forward(), r = c.right(), u = c.true_up();
  // Half extents of the box's projection: tangents at unit depth, or world units (ortho).
  double hx = 0, hy = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p{i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z};
    const Vec3 d = p - c.eye;
    const double z = c.ortho ? 1.0 : dot(d, f);
    if (!(z > 0)) throw InputError("camera", "fit", "a corner of the bounding box is behind the eye");
    hx = std::max(hx, std::fabs(dot(d, r)) / z);
    hy = std::max(hy, std::fabs(dot(d, u)) / z);
  }
  if (!(hx > 0 && hy > 0)) throw InputError("camera", "fit", "the bounding box projects to a line or a point");
  Camera out = c;
  const double aspect = hx / hy;
  out.height = std::clamp(static_cast<int>(std::lround(std::sqrt(double(pixels) / aspect))), 1, kMaxSide);
  out.width = std::clamp(static_cast<int>(std::lround(double(pixels) / out.height)), 1, kMaxSide);
  // Rounding moves the window's aspect off the box's: frame the tighter side.
  const double half_y = std::max(hy, hx * out.height / out.width);
  if (c.ortho)
    out.ortho_height = 2 * half_y;
  else
    out.fov_deg = 2 * std::atan(half_y) * 180.0 / 3.14159265358979323846;
  out.validate();
  return out;
}

}  // namespace vob
