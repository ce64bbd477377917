#include "harness/view/camera.h"

#include <cmath>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Vec3 Camera::forward() const { return normalize(target - eye); }
Vec3 Camera::right() const { return normalize(cross(forward(), up)); }
Vec3 Camera::true_up() const { return cross(right(), forward()); }

void Camera::validate() const {
  if (!is_finite(eye) || !is_finite(target) || !is_finite(up))
    throw InputError("camera", "eye/target/up", "not finite");
  if (length(target - eye) == 0) throw InputError("camera", "eye", "equals the target");
  const Vec3 f = forward();
  if (length(cross(f, normalize(up))) < 1e-9)
    throw InputError("camera", "up", "is parallel to the view direction");
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw InputError("camera", "size", std::to_string(width) + "x" + std::to_string(height) +
                                           " is not within 1..16384 on each side");
  if (!ortho && !(fov_deg > 0 && fov_deg < 180))
    throw InputError("camera", "fov", "must be in (0, 180) degrees");
  if (ortho && !(ortho_height > 0 && std::isfinite(ortho_height)))
    throw InputError("camera", "ortho", "view height must be positive");
}

Camera::HalfExtents Camera::half_extents() const {
  const double aspect = double(width) / height;
  const double y = ortho ? 0.5 * ortho_height : std::tan(0.5 * fov_deg * kPi / 180.0);
  return {y * aspect, y};
}

Ray Camera::ray(double wx, double wy) const {
  const Vec3 f = forward(), r = right(), u = true_up();
  const double aspect = double(width) / height;
  const double nx = 2.0 * wx / width - 1.0, ny = 2.0 * wy / height - 1.0;
  if (ortho) {
    const double hh = 0.5 * ortho_height, hw = hh * aspect;
    return {eye + r * (nx * hw) + u * (ny * hh), f};
  }
  const double th = std::tan(0.5 * fov_deg * kPi / 180.0);
  return {eye, normalize(f + r * (nx * th * aspect) + u * (ny * th))};
}

bool Camera::project(Vec3 p, double& wx, double& wy, double& view_depth) const {
  const Vec3 f = forward(), r = right(), u = true_up();
  const Vec3 d = p - eye;
  const double xc = dot(d, r), yc = dot(d, u), zc = dot(d, f);
  view_depth = zc;
  const double aspect = double(width) / height;
  double nx, ny;
  if (ortho) {
    const double hh = 0.5 * ortho_height;
    nx = xc / (hh * aspect);
    ny = yc / hh;
  } else {
    if (!(zc > 0)) return false;
    const double th = std::tan(0.5 * fov_deg * kPi / 180.0);
    nx = xc / (zc * th * aspect);
    ny = yc / (zc * th);
  }
  wx = 0.5 * (nx + 1.0) * width;
  wy = 0.5 * (ny + 1.0) * height;
  return true;
}

double Camera::depth(Vec3 p) const {
  return ortho ? dot(p - eye, forward()) : length(p - eye);
}

nlohmann::json Camera::to_json() const {
  nlohmann::json j{{"eye", {eye.x, eye.y, eye.z}},
                   {"target", {target.x, target.y, target.z}},
                   {"up", {up.x, up.y, up.z}},
                   {"width", width},
                   {"height", height}};
  if (ortho)
    j["ortho_height"] = ortho_height;
  else
    j["fov"] = fov_deg;
  return j;
}

Camera Camera::from_json(const nlohmann::json& j) {
  auto v = [&](const char* k) {
    const auto& a = j.at(k);
    if (!a.is_array() || a.size() != 3) throw InputError("camera", k, "needs 3 numbers");
    return Vec3{a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
  };
  Camera c;
  c.eye = v("eye");
  c.target = v("target");
  c.up = v("up");
  c.width = j.at("width").get<int>();
  c.height = j.at("height").get<int>();
  if (j.contains("ortho_height") && j.contains("fov"))
    throw InputError("camera", "fov and ortho_height", "name two projections: give one");
  if (j.contains("ortho_height")) {
    c.ortho = true;
    c.ortho_height = j["ortho_height"].get<double>();
  } else {
    c.fov_deg = j.value("fov", 40.0);
  }
  c.validate();
  return c;
}

}  // namespace vob
