// The k-buffer of HAVS (Callahan et al., sections 3.2 and 4) as an OpenGL 4.5 core fragment
// shader on OSMesa (Mesa's llvmpipe), with image load/store for the per-pixel entries.
//
// Pipeline per frame (the face order comes from the CPU radix sort, havs_frame.h):
// - Draw pass: the faces are drawn as triangles in that order (quads split along the diagonal
//   through their lexicographically smallest vertex, as the harness rasterizer splits them),
//   projected in double precision with the harness camera (window y up, pixel centres at
//   i + 0.5, no near plane: clip z is 0, so only w > 0 survives). No colour or depth
//   attachment (a framebuffer with default width/height). For each fragment the shader
//   reads the pixel's state and k entries, does the read-modify-write of kbuffer.h
//   (kbuffer_insert: the nearest of k+1 leaves, segment to the next nearest, composited
//   front to back with the inside bit for holes) and writes them back.
// - Flush pass: a full-screen triangle pops the remaining entries nearest first
//   (kbuffer_flush) and stores the final colour; the image is read back as floats.
//
// Layout: entries in an RGBA32UI 2D array image with k layers (x = bits of d, y = bits of v,
// z = tag = face * 2 + boundary); the accumulated colour in an RGBA32F image; per-pixel state
// in an R32UI image (bits 0-7 entries held, bit 8 inside, bits 16-31 fragments seen).
//
// Depth and scalar: the shader recomputes the ray parameter t of the pixel centre in double
// from the face plane and the SampleFrame's ray terms (the same row + column sum and the same
// formulas as PolygonRaster::depth), and the scalar from the same per-face linear functions
// as FaceData::scalar_at, then rounds to float like KEntry. So where the GL rasterizer covers
// the same pixel centres as the harness rasterizer, the entries are the software k-buffer's
// bit for bit (up to double rounding in dot products). Coverage can differ for pixel centres
// within llvmpipe's 1/256-pixel vertex snapping of an edge. Compositing computes 1 - exp(-x)
// in double (range reduction and a Taylor sum; GLSL has no double exp) and accumulates in
// `precise` floats, as Shading::segment does.
//
// Draw modes:
// - Batched: one glDrawElements for all faces: the paper's way. Fragments of one pixel in
//   one draw are not ordered by any GL guarantee without fragment-shader interlock, so the
//   read-modify-write may race (the paper's Fig. 5).
// - Serialized: the faces are cut, in order, into runs whose conservative pixel rectangles do
//   not overlap; one draw per run and glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT)
//   between runs. No pixel gets two fragments in one draw, so the result is race free by the
//   GL specification. Batched minus serialized = what the race changed.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/havs/havs_frame.h"
#include "harness/render/compositor.h"
#include "harness/view/camera.h"

namespace vob::havs {

enum class GlDrawMode { Batched, Serialized };

struct GlFrameStats {
  int64_t fragments = 0;  // fragments that reached the k-buffer (from the state image)
  int draws = 0;          // draw calls of the draw pass
  int64_t triangles = 0;
};

class GlKBuffer {
 public:
  // Creates the OSMesa GL 4.5 core context (current on this thread) and uploads the faces.
  // Throws GlUnavailable when the context or a needed feature is missing.
  explicit GlKBuffer(const FaceData& fd);
  ~GlKBuffer();
  GlKBuffer(const GlKBuffer&) = delete;
  GlKBuffer& operator=(const GlKBuffer&) = delete;

  // Renders one frame: `image` gets the composited colour (row 0 at the bottom), as
  // render_kbuffer. k in [1, kMaxK]. Includes the readback and a glFinish.
  // `pixel_fragments` (optional) gets the fragments each pixel received (clamped to 65535).
  GlFrameStats render(const Camera& view, const std::vector<int32_t>& face_order, int k,
                      GlDrawMode mode, Image& image, std::vector<uint32_t>* pixel_fragments = nullptr);

  std::string version() const;
  std::string renderer() const;
  size_t bytes() const;  // GL buffers and images held

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

struct GlUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Pixel-by-pixel comparison of two images at 8 bits (each channel rounded to 0..255).
struct ImageCompare8 {
  int64_t pixels = 0, differing = 0;  // pixels with any channel differing at 8 bits
  int64_t differing_by_more_than_1 = 0;  // pixels with a channel differing by 2/255 or more
  int max_diff = 0;                   // largest channel difference, in 1/255 units
  double rms = 0;                     // RMS over all channels, in 1/255 units
  std::vector<uint8_t> mask;          // per pixel, 1 where it differs
};
ImageCompare8 compare_8bit(const Image& a, const Image& b);

}  // namespace vob::havs
