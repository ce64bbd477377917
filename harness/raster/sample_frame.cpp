#include "harness/raster/sample_frame.h"

#include <cmath>
#include <string>

#include <immintrin.h>

#include "harness/cpu_features.h"
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
  const size_t row_stride = static_cast<size_t>(rows_) + 8;
  row_soa_.assign(3 * row_stride, 0.0);
  for (int sy = 0; sy < rows_; ++sy)
    for (int a = 0; a < 3; ++a) row_soa_[a * row_stride + sy] = row_[sy][a];
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

namespace {
// Four points' project() in lanes: d = p - eye; xc, yc, zc as dot()'s (x + y) + z; then
// the scalar expressions' operations in their order. Lanes not in front keep x = y = 0.
__attribute__((target("avx2"), always_inline)) inline __m256d dot4(__m256d dx, __m256d dy, __m256d dz, Vec3 a) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, _mm256_set1_pd(a.x)), _mm256_mul_pd(dy, _mm256_set1_pd(a.y))),
                       _mm256_mul_pd(dz, _mm256_set1_pd(a.z)));
}
__attribute__((target("avx2"))) void project4(const Vec3* p, Vec3 eye, Vec3 r, Vec3 u, Vec3 f, bool ortho,
                                              double sxs, double sys, double cols, double rows,
                                              ProjectedVertex* out) {
  const __m256d dx = _mm256_sub_pd(_mm256_setr_pd(p[0].x, p[1].x, p[2].x, p[3].x), _mm256_set1_pd(eye.x));
  const __m256d dy = _mm256_sub_pd(_mm256_setr_pd(p[0].y, p[1].y, p[2].y, p[3].y), _mm256_set1_pd(eye.y));
  const __m256d dz = _mm256_sub_pd(_mm256_setr_pd(p[0].z, p[1].z, p[2].z, p[3].z), _mm256_set1_pd(eye.z));
  const __m256d xc = dot4(dx, dy, dz, r), yc = dot4(dx, dy, dz, u), zc = dot4(dx, dy, dz, f);
  const __m256d one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5);
  __m256d x, y, front;
  if (ortho) {
    x = _mm256_div_pd(xc, _mm256_set1_pd(sxs));
    y = _mm256_div_pd(yc, _mm256_set1_pd(sys));
    front = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  } else {
    x = _mm256_div_pd(xc, _mm256_mul_pd(zc, _mm256_set1_pd(sxs)));
    y = _mm256_div_pd(yc, _mm256_mul_pd(zc, _mm256_set1_pd(sys)));
    front = _mm256_cmp_pd(zc, _mm256_setzero_pd(), _CMP_GT_OQ);
  }
  x = _mm256_and_pd(front, _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(x, one), half), _mm256_set1_pd(cols)));
  y = _mm256_and_pd(front, _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(y, one), half), _mm256_set1_pd(rows)));
  alignas(32) double xs[4], ys[4];
  _mm256_store_pd(xs, x);
  _mm256_store_pd(ys, y);
  const int m = _mm256_movemask_pd(front);
  for (int i = 0; i < 4; ++i) {
    out[i].x = xs[i];
    out[i].y = ys[i];
    out[i].in_front = (m >> i) & 1;
  }
}
}  // namespace

void SampleFrame::project_all(const Vec3* p, size_t n, ProjectedVertex* out) const {
  size_t i = 0;
  if (cpu_has_avx2())
    for (; i + 4 <= n; i += 4)
      project4(p + i, eye_, r_, u_, f_, cam_.ortho, sx_scale_, sy_scale_, cols_, rows_, out + i);
  for (; i < n; ++i) out[i] = ProjectedVertex::of(*this, p[i]);
}

double SampleFrame::pixels_per_unit(double zc) const {
  return cam_.ortho ? cam_.height / cam_.ortho_height : cam_.height / (2.0 * zc * sy_scale_);
}

}  // namespace vob
