#include "harness/raster/sample_frame.h"

#include <cmath>
#include <string>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
double max_abs(Vec3 v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }
}  // namespace

SampleFrame::SampleFrame(const Camera& camera, int supersample, RasterRule rule)
    : cam_(camera), s_(supersample), rule_(rule) {
  cam_.validate();
  if (supersample < 1 || supersample > 16)
    throw InputError("oracle", "supersample", std::to_string(supersample) + " is not in [1, 16]");
  if (rule == RasterRule::gl && supersample != 1)
    throw InputError("oracle", "supersample " + std::to_string(supersample),
                     "the gl sampling rule samples pixel centres only (use supersample 1)");
  cols_ = cam_.width * s_;
  rows_ = cam_.height * s_;
  eye_ = cam_.eye;
  f_ = cam_.forward();
  r_ = cam_.right();
  u_ = cam_.true_up();
  const Camera::HalfExtents half = cam_.half_extents();
  sx_scale_ = half.x;
  sy_scale_ = half.y;
  // Normalised device coordinates of sample centres, as Camera::ray computes them.
  col_.resize(cols_);
  row_.resize(rows_);
  const Vec3 base = cam_.ortho ? eye_ : f_;
  for (int sx = 0; sx < cols_; ++sx) {
    const double nx = 2.0 * (sx + 0.5) / cols_ - 1.0;
    col_[sx] = r_ * (nx * sx_scale_);
  }
  const size_t stride = static_cast<size_t>(cols_) + 3;
  col_soa_.assign(3 * stride, 0.0);
  for (int sx = 0; sx < cols_; ++sx)
    for (int a = 0; a < 3; ++a) col_soa_[a * stride + sx] = col_[sx][a];
  for (int sy = 0; sy < rows_; ++sy) {
    const double ny = 2.0 * (sy + 0.5) / rows_ - 1.0;
    row_[sy] = base + u_ * (ny * sy_scale_);
  }
  x0_ = base - u_ * sy_scale_ - r_ * sx_scale_;
  dx_ = r_ * (2.0 * sx_scale_ / cols_);
  dy_ = u_ * (2.0 * sy_scale_ / rows_);
  for (int c = 0; c < 4; ++c)
    xmag_ = std::max(xmag_, max_abs(x((c & 1) ? cols_ - 1 : 0, (c & 2) ? rows_ - 1 : 0)));
}

Ray SampleFrame::ray(int sx, int sy) const {
  const Vec3 v = x(sx, sy);
  if (cam_.ortho) return {v, f_};
  return {eye_, normalize(v)};
}

bool SampleFrame::project(Vec3 p, double& x, double& y, double& zc) const {
  const Vec3 d = p - eye_;
  const double xc = dot(d, r_), yc = dot(d, u_);
  zc = dot(d, f_);
  if (cam_.ortho) {
    x = (xc / sx_scale_ + 1.0) * 0.5 * cols_;
    y = (yc / sy_scale_ + 1.0) * 0.5 * rows_;
    return true;
  }
  if (!(zc > 0)) return false;
  x = (xc / (zc * sx_scale_) + 1.0) * 0.5 * cols_;
  y = (yc / (zc * sy_scale_) + 1.0) * 0.5 * rows_;
  return true;
}

double SampleFrame::pixels_per_unit(double zc) const {
  return cam_.ortho ? cam_.height / cam_.ortho_height : cam_.height / (2.0 * zc * sy_scale_);
}

}  // namespace vob
