// The layer-extraction buffer machine on real OpenGL: an OSMesa (llvmpipe) 3.3 core context
// (harness/gl/osmesa_context.h), a framebuffer object with a GL_R32UI item buffer (id + 1
// per fragment, from a flat vertex attribute) and a GL_DEPTH24_STENCIL8 depth-stencil
// buffer, and the paper's pass configurations (layer_backend.h). Reads are glReadPixels of
// GL_RED_INTEGER and GL_STENCIL_INDEX rectangles straight into the caller's W x H arrays
// (GL_PACK_ROW_LENGTH = W).
//
// Coverage and depth: what the gl sampling rule describes (harness/raster/raster_rule.h).
// Per frame the vertices are projected by the harness (SampleFrame::project), snapped to
// llvmpipe's 1/256-pixel grid and handed to it as NDC with w = 1 under an identity matrix
// and a power-of-two viewport (harness/gl/window_vertices.h), so llvmpipe rasterizes
// exactly those window positions with its own fill rule; the image is not flipped. Window
// depth comes from near and far planes around the primitives' bounding sphere
// (gl_depth_range), interpolated by llvmpipe into the 24-bit buffer. A primitive with a
// vertex behind the eye is not drawn (the rule covers nothing there).
//
// Geometry: quads are drawn as two triangles split along the diagonal through their
// lexicographically smallest vertex (the harness rasterizer's split). Each pass uploads an
// index buffer of the primitives it draws.
//
// The context is created by the constructor; failure is std::runtime_error with one line
// saying what OSMesa could not do.
#pragma once
#include <memory>

#include "algorithms/stencil/layer_backend.h"

namespace vob::stencil {

class GlBackend final : public LayerBackend {
 public:
  GlBackend();
  ~GlBackend() override;
  std::string name() const override { return "gl"; }
  void set_primitives(const std::vector<Vec3>& points, const std::vector<int8_t>& sizes) override;
  void begin_frame(const Camera& view) override;
  void render_candidates(const std::vector<int32_t>& ids) override;
  void render_complexity(const std::vector<int32_t>& ids) override;
  void finish() override;
  void read_colour(const PixelRect& r, uint32_t* dst) override;
  void read_stencil(const PixelRect& r, uint8_t* dst) override;
  size_t bytes() const override;
  std::string renderer() const;  // GL_RENDERER, GL_VERSION

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vob::stencil
