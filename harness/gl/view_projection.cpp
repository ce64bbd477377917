#include "harness/gl/view_projection.h"

namespace vob::gl {

std::array<double, 16> view_projection(const Camera& view, const ProjectionOptions& opt) {
  const Vec3 f = view.forward(), r = view.right(), u = view.true_up();
  const Vec3 e = view.eye - opt.origin;  // the eye in the uploaded frame
  const Camera::HalfExtents half = view.half_extents();
  double m[4][4] = {{r.x / half.x, r.y / half.x, r.z / half.x, -dot(r, e) / half.x},
                    {u.x / half.y, u.y / half.y, u.z / half.y, -dot(u, e) / half.y},
                    {0, 0, 0, 0},
                    {0, 0, 0, 1}};
  if (!view.ortho) {
    const double w[4] = {f.x, f.y, f.z, -dot(f, e)};
    for (int j = 0; j < 4; ++j) m[3][j] = w[j];
  }
  if (opt.depth) {
    // NDC z of view depth z: orthographic 2 (z - n) / (f - n) - 1; perspective the usual
    // (z (f + n) - 2 f n) / (z (f - n)), with clip w = z.
    const double n = opt.near, fa = opt.far;
    const double a = view.ortho ? 2 / (fa - n) : (fa + n) / (fa - n);
    const double b = view.ortho ? -(fa + n) / (fa - n) : -2 * fa * n / (fa - n);
    const double row[4] = {a * f.x, a * f.y, a * f.z, -a * dot(f, e) + b};
    for (int j = 0; j < 4; ++j) m[2][j] = row[j];
  }
  if (opt.flip_y)
    for (int j = 0; j < 4; ++j) m[1][j] = -m[1][j];
  std::array<double, 16> out;
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) out[c * 4 + rr] = m[rr][c];
  return out;
}

}  // namespace vob::gl
