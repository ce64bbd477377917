#include "algorithms/stencil/gl_backend.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "harness/gl/gl_functions.h"
#include "harness/gl/osmesa_context.h"
#include "harness/gl/shader_program.h"
#include "harness/gl/window_vertices.h"
#include "algorithms/stencil/shaders.h"
#include "algorithms/stencil/software_backend.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/raster_rule.h"
#include "harness/raster/sample_frame.h"
#include "harness/scene/input_error.h"

namespace vob::stencil {

namespace {

struct Vertex {
  float x, y, z;
  uint32_t item;
};

}  // namespace

struct GlBackend::Impl {
  gl::OsmesaContext ctx{gl::ContextRequest{64, 64, 3, 3, true, 24, 8}};
  gl::Functions gl{ctx};

  GLuint program = 0, vao = 0, vbo = 0, ibo = 0, fbo = 0, colour_rb = 0, depth_rb = 0;
  GLint mvp_loc = -1;
  int w = 0, h = 0;
  gl::Pow2Viewport viewport{1, 1};
  std::vector<uint32_t> first;   // per primitive: first vertex
  std::vector<uint8_t> count;    // per primitive: 3 or 6 vertices
  std::vector<Vec3> world;       // per vertex: its world position
  std::vector<Vertex> verts;     // per vertex, per frame: NDC of its snapped window position
  std::vector<uint8_t> drawable;  // per primitive, per frame: every vertex in front of the eye
  size_t vertex_bytes = 0;
  std::vector<uint32_t> index;   // per pass
  std::vector<uint32_t> rows32;  // a read rectangle, GL row order
  std::vector<uint8_t> rows8;
  Vec3 centre{};
  double radius = 1;

  Impl() {
    program = gl::link_program(gl, {gl::shader_stage(GL_VERTEX_SHADER, {shaders::item_vert}),
                                    gl::shader_stage(GL_FRAGMENT_SHADER, {shaders::item_frag})});
    mvp_loc = gl.glGetUniformLocation(program, "mvp");
    gl.glGenVertexArrays(1, &vao);
    gl.glBindVertexArray(vao);
    gl.glGenBuffers(1, &vbo);
    gl.glGenBuffers(1, &ibo);
    gl.glBindBuffer(GL_ARRAY_BUFFER, vbo);
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    gl.glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Vertex),
                              reinterpret_cast<const void*>(offsetof(Vertex, item)));
    gl.glEnableVertexAttribArray(0);
    gl.glEnableVertexAttribArray(1);
    gl.glGenFramebuffers(1, &fbo);
    gl.glGenRenderbuffers(1, &colour_rb);
    gl.glGenRenderbuffers(1, &depth_rb);
    gl.glDisable(GL_CULL_FACE);
    gl.glDisable(GL_BLEND);
    gl.glDisable(GL_MULTISAMPLE);
    gl.glDisable(GL_DITHER);
    gl.check("setup");
  }

  ~Impl() {
    ctx.make_current();
    gl.glDeleteRenderbuffers(1, &colour_rb);
    gl.glDeleteRenderbuffers(1, &depth_rb);
    gl.glDeleteFramebuffers(1, &fbo);
    gl.glDeleteBuffers(1, &vbo);
    gl.glDeleteBuffers(1, &ibo);
    gl.glDeleteVertexArrays(1, &vao);
    gl.glDeleteProgram(program);
  }

  void resize(int width, int height) {
    if (width == w && height == h) return;
    w = width;
    h = height;
    gl.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, colour_rb);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, w, h);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_rb);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
    const GLenum status = gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("OpenGL: R32UI + DEPTH24_STENCIL8 framebuffer of " +
                               std::to_string(w) + "x" + std::to_string(h) + " is incomplete");
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    gl.glDrawBuffers(1, &buf);
    gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    viewport = gl::Pow2Viewport(w, h);  // window_vertices.h: positions reach llvmpipe exactly
    gl.glViewport(0, 0, viewport.w, viewport.h);
    gl.check("framebuffer");
  }

  // Start of both passes: depth test and writes on, colour 0, depth `depth`, stencil 0.
  void clear(bool stencil_test, float depth) {
    const GLuint zero[4] = {0, 0, 0, 0};
    if (stencil_test) gl.glEnable(GL_STENCIL_TEST);
    else gl.glDisable(GL_STENCIL_TEST);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthMask(GL_TRUE);
    gl.glStencilMask(~0u);
    gl.glClearBufferuiv(GL_COLOR, 0, zero);
    gl.glClearBufferfi(GL_DEPTH_STENCIL, 0, depth, 0);
  }

  // Rows [r.y, r.y + r.h) (GL's row order is ours: row 0 at the bottom), read in one call
  // through `rows` and copied into dst (w values a row).
  template <class T>
  void read_rows(const PixelRect& r, GLenum format, GLenum type, std::vector<T>& rows, T* dst) {
    rows.resize(size_t(r.w) * r.h);
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    gl.glReadPixels(r.x, r.y, r.w, r.h, format, type, rows.data());
    for (int k = 0; k < r.h; ++k)
      std::memcpy(dst + size_t(r.y + k) * w + r.x, &rows[size_t(k) * r.w], size_t(r.w) * sizeof(T));
  }

  void draw(const std::vector<int32_t>& ids) {
    index.clear();
    for (int32_t id : ids)
      if (drawable[size_t(id)])
        for (uint32_t k = 0; k < count[id]; ++k) index.push_back(first[id] + k);
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(index.size() * 4), index.data(), GL_STREAM_DRAW);
    if (!index.empty()) gl.glDrawElements(GL_TRIANGLES, GLsizei(index.size()), GL_UNSIGNED_INT, nullptr);
  }
};

GlBackend::GlBackend() : impl_(std::make_unique<Impl>()) {}

std::unique_ptr<LayerBackend> make_layer_backend(const std::string& name, const std::string& who) {
  if (name == "software") return std::make_unique<SoftwareBackend>();
  if (name != "gl") throw InputError(who, "backend=" + name, "unknown backend (gl or software)");
  try {
    return std::make_unique<GlBackend>();
  } catch (const std::runtime_error& e) {
    throw InputError(who, "backend=gl", std::string(e.what()) + " (use backend=software)");
  }
}
GlBackend::~GlBackend() = default;

std::string GlBackend::renderer() const {
  auto s = [&](GLenum e) {
    const auto* p = impl_->gl.glGetString(e);
    return p ? std::string(reinterpret_cast<const char*>(p)) : std::string();
  };
  return s(GL_RENDERER) + ", " + s(GL_VERSION);
}

void GlBackend::set_primitives(const std::vector<Vec3>& points, const std::vector<int8_t>& sizes) {
  Impl& g = *impl_;
  g.ctx.make_current();
  Aabb box;
  for (size_t i = 0; i < sizes.size(); ++i)
    for (int k = 0; k < sizes[i]; ++k) box.add(points[4 * i + k]);
  g.centre = sizes.empty() ? Vec3{} : (box.lo + box.hi) * 0.5;
  g.radius = sizes.empty() ? 1.0 : std::max(0.5 * length(box.hi - box.lo), 1e-300);
  std::vector<Vertex> v;
  v.reserve(sizes.size() * 3);
  g.first.resize(sizes.size());
  g.count.resize(sizes.size());
  g.world.clear();
  auto put = [&](const Vec3& p, uint32_t id) {
    g.world.push_back(p);
    v.push_back({0.f, 0.f, 0.f, id});
  };
  for (size_t i = 0; i < sizes.size(); ++i) {
    const Vec3* p = &points[4 * i];
    g.first[i] = uint32_t(v.size());
    const uint32_t id = uint32_t(i);
    if (sizes[i] == 3) {
      put(p[0], id), put(p[1], id), put(p[2], id);
      g.count[i] = 3;
    } else {
      // Split along the diagonal through the lexicographically smallest vertex, as the
      // harness rasterizer does.
      int s = 0;
      for (int k = 1; k < 4; ++k)
        if (lex_less(p[k], p[s])) s = k;
      const Vec3 &a = p[s], &b = p[(s + 1) % 4], &c = p[(s + 2) % 4], &d = p[(s + 3) % 4];
      put(a, id), put(b, id), put(c, id), put(a, id), put(c, id), put(d, id);
      g.count[i] = 6;
    }
  }
  g.verts = std::move(v);
  g.drawable.assign(sizes.size(), 1);
  g.vertex_bytes = g.verts.size() * sizeof(Vertex);
}

void GlBackend::begin_frame(const Camera& view) {
  Impl& g = *impl_;
  view.validate();
  g.ctx.make_current();
  g.resize(view.width, view.height);
  g.gl.glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
  g.gl.glUseProgram(g.program);
  g.gl.glBindVertexArray(g.vao);
  // The gl sampling rule's window coordinates (raster_rule.h), snapped to llvmpipe's grid
  // here, handed over as NDC with w = 1 under an identity matrix: llvmpipe's own snapping
  // then reproduces them bit for bit. Window depth from the same near and far planes.
  const SampleFrame frame(view, 1);
  const GlDepthRange range = gl_depth_range(view, g.centre, g.radius);
  for (size_t p = 0; p < g.first.size(); ++p) {
    bool front = true;
    for (uint32_t k = g.first[p]; k < g.first[p] + g.count[p]; ++k) {
      double x, y, zc;
      front = frame.project(g.world[k], x, y, zc) && front;
      if (!front) break;
      Vertex& v = g.verts[k];
      const auto ndc = g.viewport.ndc(gl_unsnap(gl_snap(x)), gl_unsnap(gl_snap(y)));
      v.x = ndc[0];
      v.y = ndc[1];
      v.z = float(2 * gl_window_depth(view, range, zc) - 1);
    }
    g.drawable[p] = front;  // a vertex behind the eye: the rule covers nothing, so draw nothing
  }
  g.gl.glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
  g.gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(g.verts.size() * sizeof(Vertex)), g.verts.data(),
                    GL_STREAM_DRAW);
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  g.gl.glUniformMatrix4fv(g.mvp_loc, 1, GL_FALSE, identity);
  g.gl.check("begin frame");
}

void GlBackend::render_candidates(const std::vector<int32_t>& ids) {
  Impl& g = *impl_;
  g.clear(false, 1.0f);
  g.gl.glDepthFunc(GL_LESS);
  g.draw(ids);
}

void GlBackend::render_complexity(const std::vector<int32_t>& ids) {
  Impl& g = *impl_;
  g.clear(true, 0.0f);
  g.gl.glStencilFunc(GL_ALWAYS, ~0, ~0u);
  g.gl.glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  g.gl.glDepthFunc(GL_GEQUAL);
  g.draw(ids);
}

void GlBackend::finish() {
  impl_->gl.glFinish();
  impl_->gl.check("rendering");
}

void GlBackend::read_colour(const PixelRect& r, uint32_t* dst) {
  impl_->read_rows(r, GL_RED_INTEGER, GL_UNSIGNED_INT, impl_->rows32, dst);
}

void GlBackend::read_stencil(const PixelRect& r, uint8_t* dst) {
  impl_->read_rows(r, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, impl_->rows8, dst);
}

size_t GlBackend::bytes() const {
  const Impl& g = *impl_;
  // Host-side arrays plus what the driver holds: vertices, framebuffer (4 + 4 bytes per
  // pixel) and the last index buffer.
  return g.first.capacity() * 4 + g.count.capacity() + g.index.capacity() * 4 + g.vertex_bytes +
         g.rows32.capacity() * 4 + g.rows8.capacity() +
         size_t(g.w) * g.h * 8 + g.index.size() * 4;
}

}  // namespace vob::stencil
