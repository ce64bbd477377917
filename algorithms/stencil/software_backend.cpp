#include "algorithms/stencil/software_backend.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "harness/geometry/predicates.h"
#include "harness/raster/polygon_raster.h"

namespace vob::stencil {

void SoftwareBackend::set_primitives(const std::vector<Vec3>& points,
                                     const std::vector<int8_t>& sizes) {
  points_ = points;
  sizes_ = sizes;
  Aabb box;  // the GL backend's bounding sphere (gl rule depths)
  for (size_t i = 0; i < sizes.size(); ++i)
    for (int k = 0; k < sizes[i]; ++k) box.add(points[4 * i + k]);
  centre_ = sizes.empty() ? Vec3{} : box.center();
  radius_ = sizes.empty() ? 1.0 : std::max(box.radius(), 1e-300);
  coplanar_.clear();
}

void SoftwareBackend::begin_frame(const Camera& view) {
  frame_ = std::make_unique<SampleFrame>(view, 1, rule_);
  if (rule_ == RasterRule::gl) frame_->set_gl_depth_range(gl_depth_range(view, centre_, radius_));
  w_ = frame_->cols();
  h_ = frame_->rows();
  const size_t n = size_t(w_) * h_;
  depth_.resize(n);
  colour_.resize(n);
  stencil_.resize(n);
}

void SoftwareBackend::render_candidates(const std::vector<int32_t>& ids) { draw(ids, false); }

void SoftwareBackend::render_complexity(const std::vector<int32_t>& ids) { draw(ids, true); }

void SoftwareBackend::draw(const std::vector<int32_t>& ids, bool keep_far) {
  const double cleared = keep_far ? -std::numeric_limits<double>::infinity()
                                  : std::numeric_limits<double>::infinity();
  std::fill(colour_.begin(), colour_.end(), 0u);
  std::fill(depth_.begin(), depth_.end(), cleared);
  if (keep_far) std::fill(stencil_.begin(), stencil_.end(), uint8_t(0));
  PolygonRaster raster;
  const SampleRect all = frame_->bounds();
  for (int32_t id : ids) {
    if (!raster.setup(*frame_, &points_[4 * size_t(id)], sizes_[id])) continue;
    const uint32_t c = uint32_t(id) + 1;
    raster.scan(all, [&](int sx, int sy, double t, int64_t depth24) {
      if (rule_ == RasterRule::gl) t = double(depth24);  // what llvmpipe's depth test compares
      const size_t p = size_t(sy) * w_ + sx;
      if (keep_far && stencil_[p] < 255) ++stencil_[p];  // GL_INCR on depth pass and fail
      const int tie = colour_[p] ? tie_order(id, t, int32_t(colour_[p]) - 1, depth_[p]) : 0;
      const bool wins = tie != 0 ? (keep_far ? tie > 0 : tie < 0)
                                 : (keep_far ? t >= depth_[p] : t < depth_[p]);  // GEQUAL / LESS
      if (wins) {
        depth_[p] = t;
        colour_[p] = c;
      }
    });
  }
}

int SoftwareBackend::tie_order(int32_t a, double ta, int32_t b, double tb) {
  // Exactly coplanar faces have equal true depths, so any gap is rounding: the filter only
  // spares the exact test where the depths are clearly apart.
  if (!front_ || a == b || std::abs(ta - tb) > 1e-6 * std::max(std::abs(ta), std::abs(tb))) return 0;
  const bool fa = (*front_)[size_t(a)] != 0, fb = (*front_)[size_t(b)] != 0;
  if (fa == fb || !coplanar(a, b)) return 0;
  return fa ? 1 : -1;  // the back-facing one is nearer
}

bool SoftwareBackend::coplanar(int32_t a, int32_t b) {
  const uint64_t key = (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
  auto it = coplanar_.find(key);
  if (it != coplanar_.end()) return it->second;
  const Vec3* pa = &points_[4 * size_t(a)];
  const Vec3* pb = &points_[4 * size_t(b)];
  bool on = true;
  for (int j = 0; j < sizes_[size_t(b)] && on; ++j) on = orient3d(pa[0], pa[1], pa[2], pb[j]) == 0;
  for (int j = 3; j < sizes_[size_t(a)] && on; ++j) on = orient3d(pb[0], pb[1], pb[2], pa[j]) == 0;
  return coplanar_[key] = on;
}

void SoftwareBackend::read_colour(const PixelRect& r, uint32_t* dst) {
  for (int y = r.y; y < r.y + r.h; ++y)
    std::memcpy(dst + size_t(y) * w_ + r.x, &colour_[size_t(y) * w_ + r.x], size_t(r.w) * 4);
}

void SoftwareBackend::read_stencil(const PixelRect& r, uint8_t* dst) {
  for (int y = r.y; y < r.y + r.h; ++y)
    std::memcpy(dst + size_t(y) * w_ + r.x, &stencil_[size_t(y) * w_ + r.x], size_t(r.w));
}

size_t SoftwareBackend::bytes() const {
  return points_.capacity() * sizeof(Vec3) + sizes_.capacity() + depth_.capacity() * 8 +
         colour_.capacity() * 4 + stencil_.capacity() + coplanar_.size() * 24;
}

}  // namespace vob::stencil
