#include "harness/view/view_set.h"

#include <cmath>

#include "harness/scene/input_error.h"

namespace vob {
namespace {
constexpr double kPi = 3.14159265358979323846;

Camera look_from(const Aabb& box, Vec3 dir, const ViewOptions& opt) {
  Camera c;
  const Vec3 centre = box.center();
  const double r = std::max(box.radius(), 1e-300);
  c.target = centre;
  c.eye = centre + dir * (kViewDistance * r / opt.zoom);
  // World z is up unless the view looks along it.
  c.up = std::fabs(dir.z) > 0.99 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  c.width = opt.width;
  c.height = opt.height;
  c.ortho = opt.ortho;
  c.fov_deg = kViewFov;
  c.ortho_height = 2.0 * r / opt.zoom;
  return c;
}
}  // namespace

Camera fibonacci_view(const Aabb& box, int n, int i, const ViewOptions& opt) {
  if (n <= 0) throw InputError("views", "--views", "must be at least 1");
  if (i < 0 || i >= n)
    throw InputError("views", "--view-index", std::to_string(i) + " is not in [0, " +
                                                  std::to_string(n) + ")");
  // Golden-angle spiral; offsets by half a step keep the poles out of the set.
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  const double z = 1.0 - (2.0 * i + 1.0) / n;
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = golden * i + 0.5;
  return look_from(box, Vec3{rho * std::cos(phi), rho * std::sin(phi), z}, opt);
}

std::vector<Camera> fibonacci_views(const Aabb& box, int n, const ViewOptions& opt) {
  std::vector<Camera> v;
  for (int i = 0; i < n; ++i) v.push_back(fibonacci_view(box, n, i, opt));
  return v;
}

Camera orbit_view(const Aabb& box, int frames, int f, const ViewOptions& opt) {
  if (frames <= 0) throw InputError("views", "--frames", "must be at least 1");
  const double a = 2.0 * kPi * f / frames, tilt = kPi / 6.0;
  return look_from(box, Vec3{std::cos(tilt) * std::cos(a), std::cos(tilt) * std::sin(a),
                             std::sin(tilt)},
                   opt);
}

}  // namespace vob
