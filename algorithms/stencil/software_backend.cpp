#include "algorithms/stencil/software_backend.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "harness/raster/polygon_raster.h"

namespace vob::stencil {

void SoftwareBackend::set_primitives(const std::vector<Vec3>& points,
                                     const std::vector<int8_t>& sizes) {
  points_ = points;
  sizes_ = sizes;
}

void SoftwareBackend::begin_frame(const Camera& view) {
  frame_ = std::make_unique<SampleFrame>(view, 1);
  w_ = frame_->cols();
  h_ = frame_->rows();
  const size_t n = size_t(w_) * h_;
  depth_.resize(n);
  colour_.resize(n);
  stencil_.resize(n);
}

void SoftwareBackend::render_candidates(const std::vector<int32_t>& ids) {
  std::fill(colour_.begin(), colour_.end(), 0u);
  std::fill(depth_.begin(), depth_.end(), std::numeric_limits<double>::infinity());
  PolygonRaster raster;
  const SampleRect all = frame_->bounds();
  for (int32_t id : ids) {
    if (!raster.setup(*frame_, &points_[4 * size_t(id)], sizes_[id])) continue;
    const uint32_t c = uint32_t(id) + 1;
    raster.scan(all, [&](int sx, int sy, double t) {
      const size_t p = size_t(sy) * w_ + sx;
      if (t < depth_[p]) {  // GL_LESS
        depth_[p] = t;
        colour_[p] = c;
      }
    });
  }
}

void SoftwareBackend::render_complexity(const std::vector<int32_t>& ids) {
  std::fill(colour_.begin(), colour_.end(), 0u);
  std::fill(depth_.begin(), depth_.end(), -std::numeric_limits<double>::infinity());
  std::fill(stencil_.begin(), stencil_.end(), uint8_t(0));
  PolygonRaster raster;
  const SampleRect all = frame_->bounds();
  for (int32_t id : ids) {
    if (!raster.setup(*frame_, &points_[4 * size_t(id)], sizes_[id])) continue;
    const uint32_t c = uint32_t(id) + 1;
    raster.scan(all, [&](int sx, int sy, double t) {
      const size_t p = size_t(sy) * w_ + sx;
      if (stencil_[p] < 255) ++stencil_[p];  // GL_INCR on depth pass and fail
      if (t >= depth_[p]) {                   // GL_GEQUAL
        depth_[p] = t;
        colour_[p] = c;
      }
    });
  }
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
         colour_.capacity() * 4 + stencil_.capacity();
}

}  // namespace vob::stencil
