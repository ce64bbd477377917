#include "harness/raster/raster_rule.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "harness/scene/input_error.h"

namespace vob {

RasterRule parse_raster_rule(const std::string& name, const std::string& who) {
  if (name == "exact") return RasterRule::exact;
  if (name == "gl") return RasterRule::gl;
  throw InputError(who, "'" + name + "'", "unknown sampling rule (exact or gl)");
}

void throw_beyond_gl_range(double window) {
  char v[32];
  std::snprintf(v, sizeof v, "%.6g", window);
  throw InputError("--raster gl", std::string("window coordinate ") + v,
                   "a vertex projects beyond the 2^22 pixels the gl rule describes (GL clips such a triangle, "
                   "which llvmpipe's rule here does not model: an eye inside or next to the model); use --raster exact");
}

GlDepthRange gl_depth_range(const Camera& view, const Vec3& centre, double radius) {
  GlDepthRange r;
  const double d = dot(centre - view.eye, view.forward());  // view depth of the centre
  if (view.ortho) {  // near >= 0: only what is in front of the eye plane, as in the harness
    r.near = std::max(d - 1.01 * radius, 0.0);
    r.far = std::max(d + 1.01 * radius, r.near + 1e-6 * radius);
  } else {
    r.near = std::max(d - 1.01 * radius, 1e-3 * radius);
    r.far = std::max(d + 1.01 * radius, 2 * r.near);
  }
  return r;
}

double gl_window_depth(const Camera& view, const GlDepthRange& r, double zc) {
  const double n = r.near, f = r.far;
  if (view.ortho) return (zc - n) / (f - n);
  return f * (zc - n) / ((f - n) * zc);  // (NDC z + 1) / 2 of the perspective projection
}

}  // namespace vob
