// The layer-extraction buffer machine on the harness rasterizer (polygon_raster.h): the
// same pixel centres, top-left fill rule and depths (the ray parameter t, in doubles) as
// the oracle, so the layers it yields are exact for the oracle's samples. Passes follow the
// OpenGL configurations of layer_backend.h fragment by fragment, in drawing order: GL_LESS
// keeps the first of equal depths, GL_GEQUAL the last; GL_INCR saturates at 255.
// Under the gl sampling rule (constructor) it draws what the GL backend draws: llvmpipe's
// coverage and depths compared as 24-bit values (raster_rule.h), so the two can be compared
// buffer for buffer.
// With set_facing, a depth tie between exactly coplanar faces facing opposite ways (their
// interpolated depths differ only by rounding) is decided by the facing rule instead.
#pragma once
#include <memory>
#include <unordered_map>

#include "algorithms/stencil/layer_backend.h"
#include "harness/raster/sample_frame.h"

namespace vob::stencil {

class SoftwareBackend final : public LayerBackend {
 public:
  explicit SoftwareBackend(RasterRule rule = RasterRule::exact) : rule_(rule) {}
  std::string name() const override { return "software"; }
  void set_primitives(const std::vector<Vec3>& points, const std::vector<int8_t>& sizes) override;
  void begin_frame(const Camera& view) override;
  void set_facing(const std::vector<uint8_t>* front_facing) override { front_ = front_facing; }
  void render_candidates(const std::vector<int32_t>& ids) override;
  void render_complexity(const std::vector<int32_t>& ids) override;
  void finish() override {}
  void read_colour(const PixelRect& r, uint32_t* dst) override;
  void read_stencil(const PixelRect& r, uint8_t* dst) override;
  size_t bytes() const override;

 private:
  // Draws `ids` in order; the farthest fragment wins when `keep_far` (GL_GEQUAL, counting
  // the stencil), else the nearest (GL_LESS).
  void draw(const std::vector<int32_t>& ids, bool keep_far);
  // -1 when primitive a (depth ta) is nearer than b (depth tb) by the facing rule, +1 when
  // b is, 0 when the pair is no coplanar opposite-facing tie.
  int tie_order(int32_t a, double ta, int32_t b, double tb);
  bool coplanar(int32_t a, int32_t b);

  RasterRule rule_;
  Vec3 centre_{};
  double radius_ = 1;
  std::vector<Vec3> points_;
  std::vector<int8_t> sizes_;
  std::unique_ptr<SampleFrame> frame_;
  int w_ = 0, h_ = 0;
  std::vector<double> depth_;
  std::vector<uint32_t> colour_;
  std::vector<uint8_t> stencil_;
  const std::vector<uint8_t>* front_ = nullptr;
  std::unordered_map<uint64_t, bool> coplanar_;  // exact, view-independent, by id pair
};

}  // namespace vob::stencil
