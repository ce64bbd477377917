// The layer-extraction buffer machine on real OpenGL: an OSMesa (llvmpipe) 3.3 core context
// (harness/gl/osmesa_context.h), a framebuffer object with a GL_R32UI item buffer (id + 1
// per fragment, from a flat vertex attribute) and a GL_DEPTH24_STENCIL8 depth-stencil
// buffer, and the paper's pass configurations (layer_backend.h). Reads are glReadPixels of
// GL_RED_INTEGER and GL_STENCIL_INDEX rectangles straight into the caller's W x H arrays
// (GL_PACK_ROW_LENGTH = W).
//
// Fill rule: llvmpipe owns left edges and the edges that are bottom edges in GL's y-up
// window (D3D's top-left rule in a y-down frame); the harness rasterizer owns left and top
// edges (y up). The image is therefore drawn upside down (GL row H-1-j is our row j) and
// reads flip it back: then the rules agree at pixel centres exactly on edges (a test
// checks 16 edge directions and whole scenes). What still differs: llvmpipe snaps window
// coordinates to 1/256 pixel, so centres within about 1/256 pixel of an edge may change
// sides, and depth is interpolated in floats into 24 bits.
//
// Geometry: vertices are uploaded once, in floats relative to the primitives' bounding-box
// centre; quads are drawn as two triangles split along the diagonal through their
// lexicographically smallest vertex (the harness rasterizer's split). The projection is the
// harness camera's (camera.h: OpenGL conventions), with near and far planes around the
// bounding sphere (near >= 0 in orthographic views: only what is in front of the eye plane,
// as in the harness). Each pass uploads an index buffer of the primitives it draws.
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
