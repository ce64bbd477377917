#include "algorithms/havs/gl/gl_kbuffer.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "harness/geometry/polygon_plane.h"
#include "harness/gl/osmesa_context.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"

namespace vob::havs {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The per-fragment k-buffer step and the flush share these definitions (kbuffer.h in GLSL).
const char* kCommon = R"(
#version 450 core
struct Entry { float d; float v; int tag; };
// kbuffer.h nearer(): nearer, ties by tag (face * 2 + boundary).
bool nearer(Entry a, Entry b) { return a.d < b.d || (a.d == b.d && a.tag < b.tag); }
layout(binding = 0, rgba32ui) uniform coherent uimage2DArray entries;
layout(binding = 1, rgba32f) uniform coherent image2D accum;
layout(binding = 2, r32ui) uniform coherent uimage2D pstate;
// [0] eye, ortho; [1] forward, tau0; then the SampleFrame's row terms, then its column terms.
layout(std430, binding = 2) readonly buffer FrameBuf { dvec4 frame[]; };
Entry load_entry(ivec2 px, int i) {
  uvec4 u = imageLoad(entries, ivec3(px, i));
  return Entry(uintBitsToFloat(u.x), uintBitsToFloat(u.y), int(u.z));
}
void store_entry(ivec2 px, int i, Entry e) {
  imageStore(entries, ivec3(px, i), uvec4(floatBitsToUint(e.d), floatBitsToUint(e.v), uint(e.tag), 0u));
}
// 1 - exp(-x) for x >= 0 in double (GLSL has no double exp): exp(-x) = 2^-n exp(-r) with
// r = x - n ln 2 in [0, ln 2) and a Taylor sum for exp(-r) (error below 1e-16); a series for
// small x, where 1 - exp would cancel.
double one_minus_exp_neg(double x) {
  if (x < 0.01) return x * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x / 120.0))));
  if (x > 745.0) return 1.0;
  double n = floor(x * 1.4426950408889634);
  double r = x - n * 0.6931471805599453;
  double term = 1.0, sum = 1.0;
  for (int i = 1; i <= 18; ++i) {
    term *= -r / double(i);
    sum += term;
  }
  return 1.0 - ldexp(sum, -int(n));
}
// kbuffer.h Shading::segment: the boundary flip, then n1 -> n2 front to back when inside.
void segment(inout precise vec4 acc, inout bool inside, Entry n1, Entry n2) {
  if ((n1.tag & 1) != 0) inside = !inside;
  if (!inside) return;
  double tau0 = frame[1].w;
  double s = 0.5 * (double(n1.v) + double(n2.v));
  double x = tau0 * (0.25 + 0.75 * s) * (double(n2.d) - double(n1.d));
  double alpha = one_minus_exp_neg(x);
  precise float w = float((1.0 - double(acc.a)) * alpha);
  acc.r += w * float(0.15 + s * 0.85);
  acc.g += w * float(0.80 - s * 0.45);
  acc.b += w * float(0.30 + s * 0.40);
  acc.a += w;
}
)";

const char* kDrawVertex = R"(
#version 450 core
layout(location = 0) in dvec3 pos;
layout(location = 1) in int tag;
uniform dmat4 mvp;
flat out int vtag;
void main() {
  gl_Position = vec4(mvp * dvec4(pos, 1.0));
  vtag = tag;
}
)";

const char* kDrawFragment = R"(
flat in int vtag;
uniform int nrows;
struct Face { dvec4 plane; dvec4 onp; dvec4 s1; };  // n, d; a point on the plane, quad slot; g, c
layout(std430, binding = 0) readonly buffer FaceBuf { Face faces[]; };
layout(std430, binding = 1) readonly buffer QuadBuf { dvec4 quads[]; };  // per quad: half 0-2-3, split
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  // PolygonRaster::depth at the sample's X = row(sy) + col(sx), and FaceData::scalar_at.
  dvec3 X = frame[2 + px.y].xyz + frame[2 + nrows + px.x].xyz;
  Face F = faces[vtag >> 1];
  dvec3 n = F.plane.xyz;
  bool ortho = frame[0].w != 0.0;
  dvec3 eye = frame[0].xyz;
  double t;
  dvec3 p;
  if (ortho) {
    t = -(dot(n, X) + F.plane.w) * (1.0 / dot(n, frame[1].xyz));
    p = X + frame[1].xyz * t;
  } else {
    double num = -dot(n, eye - F.onp.xyz);
    double len = sqrt(dot(X, X));
    t = num / dot(n, X) * len;
    p = eye + X * (t / len);
  }
  if (!(ortho ? t >= 0.0 : t > 0.0) || isinf(t) || isnan(t)) discard;
  int q = int(F.onp.w);
  double s = (q >= 0 && dot(quads[2 * q + 1].xyz, p) + quads[2 * q + 1].w > 0.0)
                 ? dot(quads[2 * q].xyz, p) + quads[2 * q].w
                 : dot(F.s1.xyz, p) + F.s1.w;
  Entry f = Entry(float(t), float(clamp(s, 0.0, 1.0)), vtag);

  // kbuffer_insert: read, modify, write. Without interlock nothing orders this sequence
  // against another fragment of the same pixel in the same draw (Fig. 5).
  uint st = imageLoad(pstate, px).x;
  uint count = st & 0xffu;
  bool inside = (st & 0x100u) != 0u;
  uint frags = min((st >> 16) + 1u, 0xffffu);
  if (count < uint(K)) {
    store_entry(px, int(count), f);
    imageStore(pstate, px, uvec4((count + 1u) | (st & 0x100u) | (frags << 16)));
    return;
  }
  Entry e[K];
  for (int i = 0; i < K; ++i) e[i] = load_entry(px, i);
  int ni = -1;
  Entry n1 = f;
  for (int i = 0; i < K; ++i)
    if (nearer(e[i], n1)) { n1 = e[i]; ni = i; }
  if (ni >= 0) { e[ni] = f; store_entry(px, ni, f); }
  int j = 0;
  for (int i = 1; i < K; ++i)
    if (nearer(e[i], e[j])) j = i;
  precise vec4 acc = imageLoad(accum, px);
  segment(acc, inside, n1, e[j]);
  imageStore(accum, px, acc);
  imageStore(pstate, px, uvec4(count | (inside ? 0x100u : 0u) | (frags << 16)));
}
)";

const char* kFlushVertex = R"(
#version 450 core
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

const char* kFlushFragment = R"(
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  uint st = imageLoad(pstate, px).x;
  int count = int(st & 0xffu);
  bool inside = (st & 0x100u) != 0u;
  if (count < 2) return;
  Entry e[K];
  for (int i = 0; i < K; ++i)
    if (i < count) e[i] = load_entry(px, i);
  precise vec4 acc = imageLoad(accum, px);
  // kbuffer_flush: pop the nearest, composite it with the next nearest.
  while (count >= 2) {
    int i = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[i])) i = q;
    Entry n1 = e[i];
    --count;
    e[i] = e[count];
    int j = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[j])) j = q;
    segment(acc, inside, n1, e[j]);
  }
  imageStore(accum, px, acc);
}
)";

struct GpuVertex {
  double x, y, z;
  int32_t tag, pad;
};
struct GpuFace {
  double n[3], d;
  double onp[3], quad;
  double g[3], c;
};

}  // namespace

struct GlKBuffer::Impl {
  gl::OsmesaContext ctx;
#define VOB_GL(type, name) type name = ctx.load<type>(#name)
  VOB_GL(PFNGLGETERRORPROC, glGetError);
  VOB_GL(PFNGLCREATESHADERPROC, glCreateShader);
  VOB_GL(PFNGLSHADERSOURCEPROC, glShaderSource);
  VOB_GL(PFNGLCOMPILESHADERPROC, glCompileShader);
  VOB_GL(PFNGLGETSHADERIVPROC, glGetShaderiv);
  VOB_GL(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog);
  VOB_GL(PFNGLDELETESHADERPROC, glDeleteShader);
  VOB_GL(PFNGLCREATEPROGRAMPROC, glCreateProgram);
  VOB_GL(PFNGLATTACHSHADERPROC, glAttachShader);
  VOB_GL(PFNGLLINKPROGRAMPROC, glLinkProgram);
  VOB_GL(PFNGLGETPROGRAMIVPROC, glGetProgramiv);
  VOB_GL(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog);
  VOB_GL(PFNGLDELETEPROGRAMPROC, glDeleteProgram);
  VOB_GL(PFNGLUSEPROGRAMPROC, glUseProgram);
  VOB_GL(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation);
  VOB_GL(PFNGLPROGRAMUNIFORM1IPROC, glProgramUniform1i);
  VOB_GL(PFNGLPROGRAMUNIFORMMATRIX4DVPROC, glProgramUniformMatrix4dv);
  VOB_GL(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays);
  VOB_GL(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays);
  VOB_GL(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray);
  VOB_GL(PFNGLVERTEXARRAYVERTEXBUFFERPROC, glVertexArrayVertexBuffer);
  VOB_GL(PFNGLVERTEXARRAYELEMENTBUFFERPROC, glVertexArrayElementBuffer);
  VOB_GL(PFNGLVERTEXARRAYATTRIBLFORMATPROC, glVertexArrayAttribLFormat);
  VOB_GL(PFNGLVERTEXARRAYATTRIBIFORMATPROC, glVertexArrayAttribIFormat);
  VOB_GL(PFNGLVERTEXARRAYATTRIBBINDINGPROC, glVertexArrayAttribBinding);
  VOB_GL(PFNGLENABLEVERTEXARRAYATTRIBPROC, glEnableVertexArrayAttrib);
  VOB_GL(PFNGLCREATEBUFFERSPROC, glCreateBuffers);
  VOB_GL(PFNGLDELETEBUFFERSPROC, glDeleteBuffers);
  VOB_GL(PFNGLNAMEDBUFFERDATAPROC, glNamedBufferData);
  VOB_GL(PFNGLBINDBUFFERBASEPROC, glBindBufferBase);
  VOB_GL(PFNGLCREATETEXTURESPROC, glCreateTextures);
  VOB_GL(PFNGLDELETETEXTURESPROC, glDeleteTextures);
  VOB_GL(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D);
  VOB_GL(PFNGLTEXTURESTORAGE3DPROC, glTextureStorage3D);
  VOB_GL(PFNGLCLEARTEXIMAGEPROC, glClearTexImage);
  VOB_GL(PFNGLBINDIMAGETEXTUREPROC, glBindImageTexture);
  VOB_GL(PFNGLGETTEXTUREIMAGEPROC, glGetTextureImage);
  VOB_GL(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers);
  VOB_GL(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers);
  VOB_GL(PFNGLNAMEDFRAMEBUFFERPARAMETERIPROC, glNamedFramebufferParameteri);
  VOB_GL(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus);
  VOB_GL(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  VOB_GL(PFNGLVIEWPORTPROC, glViewport);
  VOB_GL(PFNGLDISABLEPROC, glDisable);
  VOB_GL(PFNGLDRAWELEMENTSPROC, glDrawElements);
  VOB_GL(PFNGLDRAWARRAYSPROC, glDrawArrays);
  VOB_GL(PFNGLMEMORYBARRIERPROC, glMemoryBarrier);
  VOB_GL(PFNGLFINISHPROC, glFinish);
#undef VOB_GL

  const FaceData* fd = nullptr;
  GLuint vao = 0, vbo = 0, ibo = 0, face_ssbo = 0, quad_ssbo = 0, frame_ssbo = 0, fbo = 0;
  GLuint tex_entries = 0, tex_accum = 0, tex_state = 0;
  int tex_w = 0, tex_h = 0, tex_k = 0, fbo_w = 0, fbo_h = 0;
  size_t static_bytes = 0, ibo_bytes = 0;
  std::vector<uint32_t> face_first;     // per face: first index in face_indices
  std::vector<uint32_t> face_indices;   // per face: 3 or 6 vertex indices
  std::vector<uint32_t> frame_indices;  // per frame, in drawing order
  struct Programs {
    GLuint draw = 0, flush = 0;
    GLint mvp = -1, nrows = -1;
  };
  std::map<int, Programs> programs;

  explicit Impl(const FaceData& f);
  ~Impl();
  void check(const char* what) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "GL error 0x%04x in %s", unsigned(e), what);
      throw std::runtime_error(buf);
    }
  }
  GLuint shader(GLenum type, const std::vector<const char*>& src) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, GLsizei(src.size()), src.data(), nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[4096] = {0};
      glGetShaderInfoLog(s, sizeof log, nullptr, log);
      glDeleteShader(s);
      throw GlUnavailable(std::string("GL k-buffer shader does not compile: ") + log);
    }
    return s;
  }
  GLuint program(const std::vector<const char*>& vs, const std::vector<const char*>& fs) {
    const GLuint v = shader(GL_VERTEX_SHADER, vs), f = shader(GL_FRAGMENT_SHADER, fs);
    const GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[4096] = {0};
      glGetProgramInfoLog(p, sizeof log, nullptr, log);
      glDeleteProgram(p);
      throw GlUnavailable(std::string("GL k-buffer program does not link: ") + log);
    }
    return p;
  }
  const Programs& programs_for(int k) {
    auto it = programs.find(k);
    if (it != programs.end()) return it->second;
    // kCommon starts with #version; K goes after it.
    const std::string def = "#define K " + std::to_string(k) + "\n";
    const std::string common(kCommon);
    const size_t eol = common.find('\n', common.find("#version")) + 1;
    const std::string head = common.substr(0, eol), body = common.substr(eol);
    Programs p;
    p.draw = program({kDrawVertex}, {head.c_str(), def.c_str(), body.c_str(), kDrawFragment});
    p.flush = program({kFlushVertex}, {head.c_str(), def.c_str(), body.c_str(), kFlushFragment});
    p.mvp = glGetUniformLocation(p.draw, "mvp");
    p.nrows = glGetUniformLocation(p.draw, "nrows");
    check("program creation");
    return programs[k] = p;
  }
  void ensure_targets(int w, int h, int k) {
    if (w != tex_w || h != tex_h || k != tex_k) {
      if (tex_entries) {
        const GLuint t[3] = {tex_entries, tex_accum, tex_state};
        glDeleteTextures(3, t);
      }
      glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &tex_entries);
      glTextureStorage3D(tex_entries, 1, GL_RGBA32UI, w, h, k);
      glCreateTextures(GL_TEXTURE_2D, 1, &tex_accum);
      glTextureStorage2D(tex_accum, 1, GL_RGBA32F, w, h);
      glCreateTextures(GL_TEXTURE_2D, 1, &tex_state);
      glTextureStorage2D(tex_state, 1, GL_R32UI, w, h);
      tex_w = w, tex_h = h, tex_k = k;
      check("image allocation");
    }
    if (w != fbo_w || h != fbo_h) {
      if (fbo) glDeleteFramebuffers(1, &fbo);
      glCreateFramebuffers(1, &fbo);
      glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, w);
      glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, h);
      if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlUnavailable("GL k-buffer: a framebuffer without attachments is not complete");
      fbo_w = w, fbo_h = h;
    }
  }
};

GlKBuffer::Impl::Impl(const FaceData& f)
    : ctx([] {
        gl::ContextRequest r;
        r.width = r.height = 16;  // rendering goes to a framebuffer without attachments
        r.depth_bits = 0;
        r.stencil_bits = 0;
        return r;
      }()),
      fd(&f) {
  // The context is GL 4.5 core (image load/store and fp64 are core since 4.2 and 4.0); the
  // extension is checked as well, for an implementation that would advertise 4.5 falsely.
  if (!ctx.has_extension("GL_ARB_shader_image_load_store"))
    throw GlUnavailable("GL k-buffer needs image load/store (GL 4.2 or GL_ARB_shader_image_load_store)");
  const MeshFaces& mf = *f.faces;
  const CellMesh& m = f.scene.mesh();
  const size_t nf = mf.num_faces();
  std::vector<GpuVertex> verts;
  std::vector<GpuFace> faces(nf);
  std::vector<double> quads;
  face_first.resize(nf + 1);
  for (size_t i = 0; i < nf; ++i) {
    const int n = mf.face_size(i);
    const int32_t* id = mf.face_points(i);
    Vec3 v[4];
    for (int j = 0; j < n; ++j) v[j] = m.points[id[j]];
    const uint32_t base = uint32_t(verts.size());
    const int32_t tag = int32_t(i) * 2 + f.boundary[i];
    for (int j = 0; j < n; ++j) verts.push_back({v[j].x, v[j].y, v[j].z, tag, 0});
    face_first[i] = uint32_t(face_indices.size());
    // PolygonRaster's plane and quad split.
    GpuFace& g = faces[i];
    Vec3 nrm, on = v[0];
    if (n == 3) {
      nrm = cross(v[1] - v[0], v[2] - v[0]);
      face_indices.insert(face_indices.end(), {base, base + 1, base + 2});
    } else {
      const PolygonPlane pp = newell_plane(v, 4);
      nrm = pp.normal;
      on = pp.centroid;
      int mi = 0;
      for (int j = 1; j < 4; ++j)
        if (lex_less(v[j], v[mi])) mi = j;
      const auto at = [&](int j) { return base + uint32_t((mi + j) % 4); };
      face_indices.insert(face_indices.end(), {at(0), at(1), at(2), at(0), at(2), at(3)});
    }
    g.n[0] = nrm.x, g.n[1] = nrm.y, g.n[2] = nrm.z;
    g.d = -dot(nrm, on);
    g.onp[0] = on.x, g.onp[1] = on.y, g.onp[2] = on.z;
    g.quad = f.quad_slot[i];
    const FaceData::Linear& s = f.scalar[i];
    g.g[0] = s.g.x, g.g[1] = s.g.y, g.g[2] = s.g.z;
    g.c = s.c;
  }
  face_first[nf] = uint32_t(face_indices.size());
  for (size_t q = 0; q < f.quad_half2.size(); ++q)
    for (const FaceData::Linear* l : {&f.quad_half2[q], &f.quad_split[q]})
      quads.insert(quads.end(), {l->g.x, l->g.y, l->g.z, l->c});
  if (quads.empty()) quads.assign(4, 0.0);  // a buffer may not be empty
  if (faces.empty()) faces.resize(1);

  glCreateBuffers(1, &vbo);
  glNamedBufferData(vbo, GLsizeiptr(verts.size() * sizeof(GpuVertex)), verts.data(), GL_STATIC_DRAW);
  glCreateBuffers(1, &face_ssbo);
  glNamedBufferData(face_ssbo, GLsizeiptr(faces.size() * sizeof(GpuFace)), faces.data(), GL_STATIC_DRAW);
  glCreateBuffers(1, &quad_ssbo);
  glNamedBufferData(quad_ssbo, GLsizeiptr(quads.size() * sizeof(double)), quads.data(), GL_STATIC_DRAW);
  glCreateBuffers(1, &frame_ssbo);
  glCreateBuffers(1, &ibo);
  static_bytes = verts.size() * sizeof(GpuVertex) + faces.size() * sizeof(GpuFace) + quads.size() * 8;
  glCreateVertexArrays(1, &vao);
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(GpuVertex));
  glVertexArrayAttribLFormat(vao, 0, 3, GL_DOUBLE, 0);
  glVertexArrayAttribIFormat(vao, 1, 1, GL_INT, 3 * sizeof(double));
  glVertexArrayAttribBinding(vao, 0, 0);
  glVertexArrayAttribBinding(vao, 1, 0);
  glEnableVertexArrayAttrib(vao, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayElementBuffer(vao, ibo);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  check("upload");
}

GlKBuffer::Impl::~Impl() {
  try {
    ctx.make_current();
  } catch (const std::exception&) {
    return;  // the context goes with ctx; nothing else to release
  }
  for (auto& [k, p] : programs) {
    glDeleteProgram(p.draw);
    glDeleteProgram(p.flush);
  }
  const GLuint bufs[5] = {vbo, ibo, face_ssbo, quad_ssbo, frame_ssbo};
  glDeleteBuffers(5, bufs);
  glDeleteVertexArrays(1, &vao);
  if (tex_entries) {
    const GLuint t[3] = {tex_entries, tex_accum, tex_state};
    glDeleteTextures(3, t);
  }
  if (fbo) glDeleteFramebuffers(1, &fbo);
}

GlKBuffer::GlKBuffer(const FaceData& fd) {
  try {
    impl_ = std::make_unique<Impl>(fd);
  } catch (const GlUnavailable&) {
    throw;
  } catch (const std::exception& e) {
    throw GlUnavailable(e.what());
  }
}

GlKBuffer::~GlKBuffer() = default;

std::string GlKBuffer::version() const { return impl_->ctx.version(); }
std::string GlKBuffer::renderer() const { return impl_->ctx.renderer(); }

size_t GlKBuffer::bytes() const {
  const Impl& d = *impl_;
  const size_t px = size_t(d.tex_w) * d.tex_h;
  return d.static_bytes + d.ibo_bytes + px * (16 * size_t(d.tex_k) + 16 + 4) +
         (d.face_first.capacity() + d.face_indices.capacity() + d.frame_indices.capacity()) * 4;
}

GlFrameStats GlKBuffer::render(const Camera& view, const std::vector<int32_t>& face_order, int k,
                               GlDrawMode mode, Image& image, std::vector<uint32_t>* pixel_fragments) {
  if (k < 1 || k > kMaxK) throw std::invalid_argument("GL k-buffer: k out of range");
  Impl& d = *impl_;
  d.ctx.make_current();
  const SampleFrame frame(view, 1);
  const int w = frame.cols(), h = frame.rows();
  const Impl::Programs& prog = d.programs_for(k);
  d.ensure_targets(w, h, k);

  // Per-view data: the camera as a double matrix, and the sample frame's ray terms.
  const Vec3 eye = frame.eye(), fw = frame.forward(), r = view.right(), u = view.true_up();
  const double aspect = double(view.width) / view.height;
  double sx, sy;  // clip x = (p - eye).r / sx, clip y = (p - eye).u / sy
  if (view.ortho) {
    sy = 0.5 * view.ortho_height;
    sx = sy * aspect;
  } else {
    sy = std::tan(0.5 * view.fov_deg * kPi / 180.0);
    sx = sy * aspect;
  }
  double rows[4][4] = {{r.x / sx, r.y / sx, r.z / sx, -dot(r, eye) / sx},
                       {u.x / sy, u.y / sy, u.z / sy, -dot(u, eye) / sy},
                       {0, 0, 0, 0},
                       {0, 0, 0, 1}};
  if (!view.ortho) {
    const double rw[4] = {fw.x, fw.y, fw.z, -dot(fw, eye)};
    std::copy(rw, rw + 4, rows[3]);
  }
  double mvp[16];  // column major
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) mvp[c * 4 + rr] = rows[rr][c];
  std::vector<double> fb;
  fb.reserve(size_t(8 + 4 * (w + h)));
  fb.insert(fb.end(), {eye.x, eye.y, eye.z, view.ortho ? 1.0 : 0.0, fw.x, fw.y, fw.z, d.fd->tau0});
  for (int y = 0; y < h; ++y) {
    const Vec3 t = frame.row_term(y);
    fb.insert(fb.end(), {t.x, t.y, t.z, 0.0});
  }
  for (int x = 0; x < w; ++x) {
    const Vec3 t = frame.col_term(x);
    fb.insert(fb.end(), {t.x, t.y, t.z, 0.0});
  }
  d.glNamedBufferData(d.frame_ssbo, GLsizeiptr(fb.size() * 8), fb.data(), GL_STREAM_DRAW);

  // The faces' triangles in drawing order; in serialized mode, runs of faces whose pixel
  // rectangles (conservative: projected vertices, one pixel of margin) do not overlap.
  d.frame_indices.clear();
  std::vector<std::pair<size_t, size_t>> runs;  // [first index, end index)
  std::vector<int32_t> stamp;
  if (mode == GlDrawMode::Serialized) stamp.assign(size_t(w) * h, -1);
  int32_t run = 0;
  size_t run_start = 0;
  for (const int32_t f : face_order) {
    if (mode == GlDrawMode::Serialized) {
      const int n = d.fd->faces->face_size(f);
      const int32_t* id = d.fd->faces->face_points(f);
      double lx = 1e300, hx = -1e300, ly = 1e300, hy = -1e300;
      bool all_front = true;
      for (int j = 0; j < n && all_front; ++j) {
        double x, y, zc;
        if (!frame.project(d.fd->scene.mesh().points[id[j]], x, y, zc)) {
          all_front = false;
          break;
        }
        lx = std::min(lx, x), hx = std::max(hx, x), ly = std::min(ly, y), hy = std::max(hy, y);
      }
      SampleRect rect = all_front ? SampleRect{floor_to_int(lx - 0.5) - 1, floor_to_int(ly - 0.5) - 1,
                                               ceil_to_int(hx - 0.5) + 1, ceil_to_int(hy - 0.5) + 1}
                                  : frame.bounds();
      rect = rect.intersect(frame.bounds());
      if (!rect.empty()) {
        bool overlap = false;
        for (int y = rect.y0; y <= rect.y1 && !overlap; ++y)
          for (int x = rect.x0; x <= rect.x1; ++x)
            if (stamp[size_t(y) * w + x] == run) {
              overlap = true;
              break;
            }
        if (overlap) {
          runs.emplace_back(run_start, d.frame_indices.size());
          run_start = d.frame_indices.size();
          ++run;
        }
        for (int y = rect.y0; y <= rect.y1; ++y)
          std::fill_n(stamp.begin() + size_t(y) * w + rect.x0, rect.x1 - rect.x0 + 1, run);
      }
    }
    d.frame_indices.insert(d.frame_indices.end(), d.face_indices.begin() + d.face_first[f],
                           d.face_indices.begin() + d.face_first[f + 1]);
  }
  runs.emplace_back(run_start, d.frame_indices.size());
  d.ibo_bytes = std::max(d.ibo_bytes, d.frame_indices.size() * 4);
  d.glNamedBufferData(d.ibo, GLsizeiptr(d.frame_indices.size() * 4), d.frame_indices.data(), GL_STREAM_DRAW);

  // Clear the state (no entries, outside, no fragments) and the colour.
  const uint32_t zero_u[4] = {0, 0, 0, 0};
  const float zero_f[4] = {0, 0, 0, 0};
  d.glClearTexImage(d.tex_state, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, zero_u);
  d.glClearTexImage(d.tex_accum, 0, GL_RGBA, GL_FLOAT, zero_f);
  d.glBindImageTexture(0, d.tex_entries, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32UI);
  d.glBindImageTexture(1, d.tex_accum, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  d.glBindImageTexture(2, d.tex_state, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  d.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, d.face_ssbo);
  d.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, d.quad_ssbo);
  d.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, d.frame_ssbo);
  d.glBindFramebuffer(GL_FRAMEBUFFER, d.fbo);
  d.glViewport(0, 0, w, h);
  d.glProgramUniformMatrix4dv(prog.draw, prog.mvp, 1, GL_FALSE, mvp);
  d.glProgramUniform1i(prog.draw, prog.nrows, h);
  d.glUseProgram(prog.draw);
  d.glBindVertexArray(d.vao);
  GlFrameStats st;
  for (const auto& [b, e] : runs) {
    if (e == b) continue;
    d.glDrawElements(GL_TRIANGLES, GLsizei(e - b), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(b * sizeof(uint32_t)));
    ++st.draws;
    if (mode == GlDrawMode::Serialized) d.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  st.triangles = int64_t(d.frame_indices.size() / 3);
  d.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  d.glUseProgram(prog.flush);
  d.glDrawArrays(GL_TRIANGLES, 0, 3);
  d.glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);

  std::vector<float> rgba(size_t(w) * h * 4);
  d.glGetTextureImage(d.tex_accum, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * 4), rgba.data());
  std::vector<uint32_t> state(size_t(w) * h);
  d.glGetTextureImage(d.tex_state, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(state.size() * 4), state.data());
  d.glFinish();
  d.check("render");
  d.glBindFramebuffer(GL_FRAMEBUFFER, 0);
  image.width = w;
  image.height = h;
  image.rgb.resize(size_t(3) * w * h);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = rgba[4 * p + c];
    st.fragments += state[p] >> 16;
  }
  if (pixel_fragments) {
    pixel_fragments->resize(state.size());
    for (size_t p = 0; p < state.size(); ++p) (*pixel_fragments)[p] = state[p] >> 16;
  }
  return st;
}

ImageCompare8 compare_8bit(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compare_8bit: images of different sizes");
  ImageCompare8 c;
  c.pixels = int64_t(a.width) * a.height;
  c.mask.assign(c.pixels, 0);
  const auto q = [](float v) { return int(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); };
  double sum = 0;
  for (int64_t p = 0; p < c.pixels; ++p) {
    int worst = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int dd = std::abs(q(a.rgb[3 * p + ch]) - q(b.rgb[3 * p + ch]));
      sum += double(dd) * dd;
      worst = std::max(worst, dd);
    }
    c.max_diff = std::max(c.max_diff, worst);
    c.mask[p] = worst != 0;
    c.differing += worst != 0;
    c.differing_by_more_than_1 += worst > 1;
  }
  c.rms = c.pixels ? std::sqrt(sum / (3.0 * c.pixels)) : 0;
  return c;
}

}  // namespace vob::havs
