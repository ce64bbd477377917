#include "algorithms/stencil/gl_backend.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "harness/gl/osmesa_context.h"
#include "algorithms/stencil/software_backend.h"
#include "harness/raster/polygon_raster.h"
#include "harness/scene/input_error.h"

namespace vob::stencil {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in uint item;
uniform mat4 mvp;
flat out uint v_item;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  v_item = item;
}
)";

const char* kFragmentShader = R"(#version 330 core
flat in uint v_item;
layout(location = 0) out uint colour;
void main() { colour = v_item + 1u; }
)";

struct Vertex {
  float x, y, z;
  uint32_t item;
};

constexpr double kPi = 3.14159265358979323846;

}  // namespace

struct GlBackend::Impl {
  gl::OsmesaContext ctx{gl::ContextRequest{64, 64, 3, 3, true, 24, 8}};
#define VOB_GL_FN(type, name) type name = ctx.load<type>(#name)
  VOB_GL_FN(PFNGLGETERRORPROC, glGetError);
  VOB_GL_FN(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers);
  VOB_GL_FN(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers);
  VOB_GL_FN(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  VOB_GL_FN(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers);
  VOB_GL_FN(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers);
  VOB_GL_FN(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer);
  VOB_GL_FN(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage);
  VOB_GL_FN(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer);
  VOB_GL_FN(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus);
  VOB_GL_FN(PFNGLDRAWBUFFERSPROC, glDrawBuffers);
  VOB_GL_FN(PFNGLREADBUFFERPROC, glReadBuffer);
  VOB_GL_FN(PFNGLCREATESHADERPROC, glCreateShader);
  VOB_GL_FN(PFNGLSHADERSOURCEPROC, glShaderSource);
  VOB_GL_FN(PFNGLCOMPILESHADERPROC, glCompileShader);
  VOB_GL_FN(PFNGLGETSHADERIVPROC, glGetShaderiv);
  VOB_GL_FN(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog);
  VOB_GL_FN(PFNGLDELETESHADERPROC, glDeleteShader);
  VOB_GL_FN(PFNGLCREATEPROGRAMPROC, glCreateProgram);
  VOB_GL_FN(PFNGLATTACHSHADERPROC, glAttachShader);
  VOB_GL_FN(PFNGLLINKPROGRAMPROC, glLinkProgram);
  VOB_GL_FN(PFNGLGETPROGRAMIVPROC, glGetProgramiv);
  VOB_GL_FN(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog);
  VOB_GL_FN(PFNGLDELETEPROGRAMPROC, glDeleteProgram);
  VOB_GL_FN(PFNGLUSEPROGRAMPROC, glUseProgram);
  VOB_GL_FN(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation);
  VOB_GL_FN(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv);
  VOB_GL_FN(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays);
  VOB_GL_FN(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays);
  VOB_GL_FN(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray);
  VOB_GL_FN(PFNGLGENBUFFERSPROC, glGenBuffers);
  VOB_GL_FN(PFNGLDELETEBUFFERSPROC, glDeleteBuffers);
  VOB_GL_FN(PFNGLBINDBUFFERPROC, glBindBuffer);
  VOB_GL_FN(PFNGLBUFFERDATAPROC, glBufferData);
  VOB_GL_FN(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer);
  VOB_GL_FN(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer);
  VOB_GL_FN(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray);
  VOB_GL_FN(PFNGLDRAWELEMENTSPROC, glDrawElements);
  VOB_GL_FN(PFNGLVIEWPORTPROC, glViewport);
  VOB_GL_FN(PFNGLENABLEPROC, glEnable);
  VOB_GL_FN(PFNGLDISABLEPROC, glDisable);
  VOB_GL_FN(PFNGLDEPTHFUNCPROC, glDepthFunc);
  VOB_GL_FN(PFNGLDEPTHMASKPROC, glDepthMask);
  VOB_GL_FN(PFNGLSTENCILFUNCPROC, glStencilFunc);
  VOB_GL_FN(PFNGLSTENCILOPPROC, glStencilOp);
  VOB_GL_FN(PFNGLSTENCILMASKPROC, glStencilMask);
  VOB_GL_FN(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv);
  VOB_GL_FN(PFNGLCLEARBUFFERFIPROC, glClearBufferfi);
  VOB_GL_FN(PFNGLFINISHPROC, glFinish);
  VOB_GL_FN(PFNGLREADPIXELSPROC, glReadPixels);
  VOB_GL_FN(PFNGLPIXELSTOREIPROC, glPixelStorei);
  VOB_GL_FN(PFNGLGETSTRINGPROC, glGetString);
#undef VOB_GL_FN

  GLuint program = 0, vao = 0, vbo = 0, ibo = 0, fbo = 0, colour_rb = 0, depth_rb = 0;
  GLint mvp_loc = -1;
  int w = 0, h = 0;
  std::vector<uint32_t> first;   // per primitive: first vertex
  std::vector<uint8_t> count;    // per primitive: 3 or 6 vertices
  size_t vertex_bytes = 0;
  std::vector<uint32_t> index;   // per pass
  std::vector<uint32_t> rows32;  // a read rectangle, GL row order
  std::vector<uint8_t> rows8;
  Vec3 centre{};
  double radius = 1;

  void check(const char* what) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR)
      throw std::runtime_error(std::string("OpenGL error 0x") + [&] {
        char b[16];
        std::snprintf(b, sizeof b, "%x", unsigned(e));
        return std::string(b);
      }() + " in " + what);
  }

  GLuint compile(GLenum type, const char* src) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[1024] = {};
      glGetShaderInfoLog(s, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("OpenGL: shader does not compile: ") + log);
    }
    return s;
  }

  Impl() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[1024] = {};
      glGetProgramInfoLog(program, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("OpenGL: program does not link: ") + log);
    }
    mvp_loc = glGetUniformLocation(program, "mvp");
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glGenBuffers(1, &ibo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Vertex),
                           reinterpret_cast<const void*>(offsetof(Vertex, item)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &colour_rb);
    glGenRenderbuffers(1, &depth_rb);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_DITHER);
    check("setup");
  }

  ~Impl() {
    ctx.make_current();
    glDeleteRenderbuffers(1, &colour_rb);
    glDeleteRenderbuffers(1, &depth_rb);
    glDeleteFramebuffers(1, &fbo);
    glDeleteBuffers(1, &vbo);
    glDeleteBuffers(1, &ibo);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
  }

  void resize(int width, int height) {
    if (width == w && height == h) return;
    w = width;
    h = height;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_rb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("OpenGL: R32UI + DEPTH24_STENCIL8 framebuffer of " +
                               std::to_string(w) + "x" + std::to_string(h) + " is incomplete");
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, w, h);
    check("framebuffer");
  }

  void draw(const std::vector<int32_t>& ids) {
    index.clear();
    for (int32_t id : ids)
      for (uint32_t k = 0; k < count[id]; ++k) index.push_back(first[id] + k);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(index.size() * 4), index.data(), GL_STREAM_DRAW);
    if (!index.empty()) glDrawElements(GL_TRIANGLES, GLsizei(index.size()), GL_UNSIGNED_INT, nullptr);
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
    const auto* p = impl_->glGetString(e);
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
  auto put = [&](const Vec3& p, uint32_t id) {
    const Vec3 d = p - g.centre;
    v.push_back({float(d.x), float(d.y), float(d.z), id});
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
  g.glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
  g.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(Vertex)), v.data(), GL_STATIC_DRAW);
  g.vertex_bytes = v.size() * sizeof(Vertex);
  g.check("vertex upload");
}

void GlBackend::begin_frame(const Camera& view) {
  Impl& g = *impl_;
  view.validate();
  g.ctx.make_current();
  g.resize(view.width, view.height);
  g.glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
  g.glUseProgram(g.program);
  g.glBindVertexArray(g.vao);
  // Model-view-projection in doubles: world = position + centre.
  const Vec3 f = view.forward(), r = view.right(), u = view.true_up();
  const Vec3 e = view.eye - g.centre;  // eye in the uploaded frame
  const double aspect = double(view.width) / view.height;
  const double d = dot(-e, f);  // view depth of the centre
  double n, fa;
  double P[4][4] = {};
  if (view.ortho) {
    n = std::max(d - 1.01 * g.radius, 0.0);
    fa = std::max(d + 1.01 * g.radius, n + 1e-6 * g.radius);
    const double hh = 0.5 * view.ortho_height, hw = hh * aspect;
    P[0][0] = 1 / hw;
    P[1][1] = 1 / hh;
    P[2][2] = -2 / (fa - n);
    P[2][3] = -(fa + n) / (fa - n);
    P[3][3] = 1;
  } else {
    n = std::max(d - 1.01 * g.radius, 1e-3 * g.radius);
    fa = std::max(d + 1.01 * g.radius, 2 * n);
    const double th = std::tan(0.5 * view.fov_deg * kPi / 180.0);
    P[0][0] = 1 / (th * aspect);
    P[1][1] = 1 / th;
    P[2][2] = (fa + n) / (n - fa);
    P[2][3] = 2 * fa * n / (n - fa);
    P[3][2] = -1;
  }
  // Upside down: GL row H-1-j is our row j. llvmpipe's fill rule owns the edges that are
  // bottom edges in GL's y-up window (D3D's top-left rule in a y-down frame); the harness
  // owns top and left edges (y up). Flipping y makes the two rules the same.
  for (int j = 0; j < 4; ++j) P[1][j] = -P[1][j];
  const double V[4][4] = {{r.x, r.y, r.z, -dot(r, e)},
                          {u.x, u.y, u.z, -dot(u, e)},
                          {-f.x, -f.y, -f.z, dot(f, e)},
                          {0, 0, 0, 1}};
  float m[16];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += P[i][k] * V[k][j];
      m[j * 4 + i] = float(s);  // column-major
    }
  g.glUniformMatrix4fv(g.mvp_loc, 1, GL_FALSE, m);
  g.check("begin frame");
}

void GlBackend::render_candidates(const std::vector<int32_t>& ids) {
  Impl& g = *impl_;
  const GLuint zero[4] = {0, 0, 0, 0};
  g.glDisable(GL_STENCIL_TEST);
  g.glEnable(GL_DEPTH_TEST);
  g.glDepthMask(GL_TRUE);
  g.glStencilMask(~0u);
  g.glClearBufferuiv(GL_COLOR, 0, zero);
  g.glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
  g.glDepthFunc(GL_LESS);
  g.draw(ids);
}

void GlBackend::render_complexity(const std::vector<int32_t>& ids) {
  Impl& g = *impl_;
  const GLuint zero[4] = {0, 0, 0, 0};
  g.glEnable(GL_STENCIL_TEST);
  g.glEnable(GL_DEPTH_TEST);
  g.glDepthMask(GL_TRUE);
  g.glStencilMask(~0u);
  g.glClearBufferuiv(GL_COLOR, 0, zero);
  g.glClearBufferfi(GL_DEPTH_STENCIL, 0, 0.0f, 0);
  g.glStencilFunc(GL_ALWAYS, ~0, ~0u);
  g.glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  g.glDepthFunc(GL_GEQUAL);
  g.draw(ids);
}

void GlBackend::finish() {
  impl_->glFinish();
  impl_->check("rendering");
}

// The image is drawn upside down (see begin_frame): our rows [y, y + h) are GL rows
// [H - y - h, H - y), read in one call and copied back in reverse row order.
void GlBackend::read_colour(const PixelRect& r, uint32_t* dst) {
  Impl& g = *impl_;
  g.rows32.resize(size_t(r.w) * r.h);
  g.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  g.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  g.glReadPixels(r.x, g.h - r.y - r.h, r.w, r.h, GL_RED_INTEGER, GL_UNSIGNED_INT, g.rows32.data());
  for (int k = 0; k < r.h; ++k)
    std::memcpy(dst + size_t(r.y + k) * g.w + r.x, &g.rows32[size_t(r.h - 1 - k) * r.w], size_t(r.w) * 4);
}

void GlBackend::read_stencil(const PixelRect& r, uint8_t* dst) {
  Impl& g = *impl_;
  g.rows8.resize(size_t(r.w) * r.h);
  g.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  g.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  g.glReadPixels(r.x, g.h - r.y - r.h, r.w, r.h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, g.rows8.data());
  for (int k = 0; k < r.h; ++k)
    std::memcpy(dst + size_t(r.y + k) * g.w + r.x, &g.rows8[size_t(r.h - 1 - k) * r.w], size_t(r.w));
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
