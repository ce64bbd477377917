// The buffer machine that Krishnan, Silva and Wei's layer extraction runs on (section 3):
// an item buffer (primitive id + 1 in the colour, 0 = background), a z-buffer and a stencil
// buffer, configured exactly as the paper's two kinds of pass, and reads of rectangles of
// the colour and stencil buffers. Two implementations: OpenGL through OSMesa (gl_backend.h)
// and the harness rasterizer (software_backend.h), so the same algorithm
// (layer_extraction.h) runs with and without OpenGL.
//
// Primitives are convex planar polygons of 3 or 4 vertices (triangles of a surface, the
// exterior faces of a cell mesh), set once per scene; their ids are their indices.
// Pixel (x, y) has its centre at window (x + 0.5, y + 0.5), row 0 at the bottom; buffers
// are W x H row-major with index y * W + x.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"
#include "harness/view/camera.h"

namespace vob::stencil {

struct PixelRect {
  int x = 0, y = 0, w = 0, h = 0;  // [x, x + w) x [y, y + h)
};

class LayerBackend {
 public:
  virtual ~LayerBackend() = default;
  virtual std::string name() const = 0;  // "gl" or "software"
  // View-independent: polygon i has points[4 * i .. 4 * i + sizes[i]) (sizes 3 or 4).
  virtual void set_primitives(const std::vector<Vec3>& points, const std::vector<int8_t>& sizes) = 0;
  // Exterior faces of cells only (stencil-xmpvo), per frame: which primitives face the eye
  // (1) and which face away (0), or null. Two exterior faces of volumes that touch face to
  // face lie in one plane and meet every ray through their overlap at one depth; a backend
  // that honours this orders such a tie exactly: the back-facing face is nearer, since the
  // ray leaves its cell before entering the other's (coplanar_order in
  // algorithms/xmpvo/face_pairs.h). The GL backend ignores it (cell scenes are not judged by the gl rule).
  virtual void set_facing(const std::vector<uint8_t>* /*front_facing*/) {}
  // Per frame: the camera fixes the buffer size (W x H) and the projection.
  virtual void begin_frame(const Camera& view) = 0;
  // Steps 1-2: clear the colour to 0 and the depth to 1.0 (far), stencil test disabled,
  // depth test GL_LESS with depth writes; draw `ids` in the given order.
  virtual void render_candidates(const std::vector<int32_t>& ids) = 0;
  // Steps 4a-4b: clear the colour to 0, the stencil to 0 and the depth to 0.0 (near);
  // stencil enabled with glStencilFunc(GL_ALWAYS, ~0, ~0), glStencilOp(GL_KEEP, GL_INCR,
  // GL_INCR); depth test GL_GEQUAL with depth writes; draw `ids` in the given order.
  virtual void render_complexity(const std::vector<int32_t>& ids) = 0;
  // Waits until the passes drawn so far are complete (glFinish), so that the read timing
  // measures reading only.
  virtual void finish() = 0;
  // Copies the rectangle of the colour (id + 1, 0 = background) or stencil buffer into
  // `dst`, a full W x H array, at the rectangle's own position.
  virtual void read_colour(const PixelRect& r, uint32_t* dst) = 0;
  virtual void read_stencil(const PixelRect& r, uint8_t* dst) = 0;
  virtual size_t bytes() const = 0;
};

// "gl" (OSMesa) or "software". When OSMesa cannot give the context the GL backend needs,
// InputError with one line naming `who`, the reason and the way out (backend=software).
std::unique_ptr<LayerBackend> make_layer_backend(const std::string& name, const std::string& who);

}  // namespace vob::stencil
