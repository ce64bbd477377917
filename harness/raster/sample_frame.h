// The sample grid of a view and the per-sample rays, precomputed once per (camera, S).
//
// With S x S samples per pixel, sample (a, b) of pixel (i, j) sits at window coordinates
// (i + (a+0.5)/S, j + (b+0.5)/S). That is one uniform grid of (W*S) x (H*S) samples: sample
// (sx, sy) = (i*S + a, j*S + b) is at window ((sx+0.5)/S, (sy+0.5)/S). "Sample coordinates"
// below are window coordinates times S, so sample (sx, sy) has its centre at (sx+0.5, sy+0.5).
// Sample index = sy * cols + sx (row 0 at the bottom, window y up).
//
// Rays: perspective rays start at the eye, ray(s) = eye + s * D(sx, sy) with an unnormalised
// direction D; orthographic rays start on the eye plane, ray(s) = O(sx, sy) + s * forward.
// The varying vector X (D or O) is row(sy) + col(sx), computed the same way by every caller,
// so that two primitives testing the same sample against a shared edge or face use
// bit-identical inputs. The ray parameter t of DESIGN.md is s * |D| (|D| = 1 in ortho).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "harness/geometry/vec3.h"
#include "harness/raster/raster_rule.h"
#include "harness/view/camera.h"

namespace vob {

// An inclusive rectangle of samples; empty when x0 > x1 or y0 > y1.
struct SampleRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
  SampleRect intersect(const SampleRect& o) const {
    return {x0 > o.x0 ? x0 : o.x0, y0 > o.y0 ? y0 : o.y0, x1 < o.x1 ? x1 : o.x1,
            y1 < o.y1 ? y1 : o.y1};
  }
  // The smallest rectangle holding both (an empty one adds nothing).
  SampleRect unite(const SampleRect& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {x0 < o.x0 ? x0 : o.x0, y0 < o.y0 ? y0 : o.y0, x1 > o.x1 ? x1 : o.x1,
            y1 > o.y1 ? y1 : o.y1};
  }
};

// floor / ceil of a sample coordinate, clamped so that far-off values stay in int range.
inline int floor_to_int(double v) { return static_cast<int>(std::floor(std::clamp(v, -1e9, 1e9))); }
inline int ceil_to_int(double v) { return static_cast<int>(std::ceil(std::clamp(v, -1e9, 1e9))); }

class SampleFrame;

// A vertex's window position as SampleFrame::project gives it (in_front false when the
// vertex is not strictly in front of the eye). Callers rasterizing many polygons that share
// vertices project each vertex once and hand these to setup(): same values, less work.
struct ProjectedVertex {
  double x = 0, y = 0;
  bool in_front = false;
  static ProjectedVertex of(const SampleFrame& frame, const Vec3& p);
};

class SampleFrame {
 public:
  // Validates the camera; supersample must be in [1, 16], and 1 under the gl rule (GL
  // samples pixel centres). InputError otherwise.
  SampleFrame(const Camera& camera, int supersample, RasterRule rule = RasterRule::exact);

  const Camera& camera() const { return cam_; }
  int supersample() const { return s_; }
  RasterRule rule() const { return rule_; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  int64_t num_samples() const { return int64_t(cols_) * rows_; }
  int64_t index(int sx, int sy) const { return int64_t(sy) * cols_ + sx; }
  SampleRect bounds() const { return {0, 0, cols_ - 1, rows_ - 1}; }
  bool ortho() const { return cam_.ortho; }

  Vec3 eye() const { return eye_; }
  Vec3 forward() const { return f_; }
  // X(sx, sy): the unnormalised direction D (perspective) or the origin O (orthographic).
  Vec3 x(int sx, int sy) const { return row_[sy] + col_[sx]; }
  const Vec3& row_term(int sy) const { return row_[sy]; }
  const Vec3& col_term(int sx) const { return col_[sx]; }
  // col_term's components as three arrays, each padded with 3 zeros past the last column
  // (for kernels that load four columns at a time).
  const double* col_x() const { return col_soa_.data(); }
  const double* col_y() const { return col_soa_.data() + (cols_ + 3); }
  const double* col_z() const { return col_soa_.data() + 2 * (cols_ + 3); }
  // row_term's components as three arrays, each padded with 8 zeros past the last row
  // (for kernels that load eight rows at a time).
  const double* row_x() const { return row_soa_.data(); }
  const double* row_y() const { return row_soa_.data() + (rows_ + 8); }
  const double* row_z() const { return row_soa_.data() + 2 * (rows_ + 8); }
  // The affine form of X in sample-centre coordinates (x, y) = (sx+0.5, sy+0.5):
  // X ~= x0 + x * dx + y * dy (for bounds and spans only; decisions use x(sx, sy)).
  Vec3 affine_origin() const { return x0_; }
  Vec3 affine_dx() const { return dx_; }
  Vec3 affine_dy() const { return dy_; }
  // Largest |component| of X over the grid: the scale of rounding errors in n . X.
  double x_magnitude() const { return xmag_; }

  // The ray of a sample with a unit direction, and |D| (1 in ortho): t = s * |D|.
  Ray ray(int sx, int sy) const;
  double dir_length(int sx, int sy) const { return cam_.ortho ? 1.0 : length(x(sx, sy)); }
  // Projects p to sample coordinates; zc = view depth (distance along forward from the eye).
  // Perspective: false when zc <= 0 (x, y are then not set).
  bool project(Vec3 p, double& x, double& y, double& zc) const;
  // ProjectedVertex::of for p[0, n) into out[0, n): the same bits, four points at a time in
  // AVX2 lanes when the CPU has them (the same operations in the same order, no FMA).
  void project_all(const Vec3* p, size_t n, ProjectedVertex* out) const;
  // Pixels per world unit at view depth zc (zc > 0 in perspective).
  double pixels_per_unit(double zc) const;
  // gl rule: the near and far planes GL's window depth is taken under (raster_rule.h). With
  // them set, PolygonRaster::scan hands emitters that take it llvmpipe's 24-bit depth.
  void set_gl_depth_range(const GlDepthRange& r) { gl_range_ = r, has_gl_range_ = true; }
  const GlDepthRange* gl_range() const { return has_gl_range_ ? &gl_range_ : nullptr; }

 private:
  Camera cam_;
  int s_, cols_, rows_;
  RasterRule rule_ = RasterRule::exact;
  Vec3 eye_, f_, r_, u_;
  double sx_scale_, sy_scale_;  // perspective: tan terms; ortho: half extents
  std::vector<Vec3> row_, col_;
  std::vector<double> col_soa_;  // col_x, col_y, col_z
  std::vector<double> row_soa_;  // row_x, row_y, row_z
  Vec3 x0_, dx_, dy_;
  double xmag_ = 0;
  GlDepthRange gl_range_;
  bool has_gl_range_ = false;
};

inline ProjectedVertex ProjectedVertex::of(const SampleFrame& frame, const Vec3& p) {
  ProjectedVertex q;
  double zc;
  q.in_front = frame.project(p, q.x, q.y, zc);
  return q;
}

}  // namespace vob
