#include <stdexcept>
#include <string>

#include "algorithms/havs/gl/gl_kbuffer_impl.h"
#include "harness/geometry/polygon_plane.h"
#include "harness/raster/polygon_raster.h"
#include "algorithms/havs/gl/shaders.h"

namespace vob::havs {
namespace {

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

  gl.glCreateBuffers(1, &vbo);
  gl.glNamedBufferData(vbo, GLsizeiptr(verts.size() * sizeof(GpuVertex)), verts.data(), GL_STATIC_DRAW);
  gl.glCreateBuffers(1, &face_ssbo);
  gl.glNamedBufferData(face_ssbo, GLsizeiptr(faces.size() * sizeof(GpuFace)), faces.data(), GL_STATIC_DRAW);
  gl.glCreateBuffers(1, &quad_ssbo);
  gl.glNamedBufferData(quad_ssbo, GLsizeiptr(quads.size() * sizeof(double)), quads.data(), GL_STATIC_DRAW);
  gl.glCreateBuffers(1, &frame_ssbo);
  gl.glCreateBuffers(1, &ibo);
  static_bytes = verts.size() * sizeof(GpuVertex) + faces.size() * sizeof(GpuFace) + quads.size() * 8;
  gl.glCreateVertexArrays(1, &vao);
  gl.glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(GpuVertex));
  gl.glVertexArrayAttribLFormat(vao, 0, 3, GL_DOUBLE, 0);
  gl.glVertexArrayAttribIFormat(vao, 1, 1, GL_INT, 3 * sizeof(double));
  gl.glVertexArrayAttribBinding(vao, 0, 0);
  gl.glVertexArrayAttribBinding(vao, 1, 0);
  gl.glEnableVertexArrayAttrib(vao, 0);
  gl.glEnableVertexArrayAttrib(vao, 1);
  gl.glVertexArrayElementBuffer(vao, ibo);
  gl.glDisable(GL_DEPTH_TEST);
  gl.glDisable(GL_CULL_FACE);
  gl.glDisable(GL_BLEND);
  gl.check("upload");
}

GlKBuffer::Impl::~Impl() {
  try {
    ctx.make_current();
  } catch (const std::exception&) {
    return;  // the context goes with ctx; nothing else to release
  }
  for (auto& [k, p] : programs) {
    gl.glDeleteProgram(p.draw);
    gl.glDeleteProgram(p.flush);
  }
  const GLuint bufs[5] = {vbo, ibo, face_ssbo, quad_ssbo, frame_ssbo};
  gl.glDeleteBuffers(5, bufs);
  gl.glDeleteVertexArrays(1, &vao);
  if (tex_entries) {
    const GLuint t[3] = {tex_entries, tex_accum, tex_state};
    gl.glDeleteTextures(3, t);
  }
  if (fbo) gl.glDeleteFramebuffers(1, &fbo);
}

const GlKBuffer::Impl::Programs& GlKBuffer::Impl::programs_for(int k) {
  auto it = programs.find(k);
  if (it != programs.end()) return it->second;
  const std::string def = "#define K " + std::to_string(k) + "\n";
  Programs p;
  try {
    p.draw = gl::link_program(gl, {gl::shader_stage(GL_VERTEX_SHADER, {shaders::draw_vert}),
                                   gl::shader_stage(GL_FRAGMENT_SHADER, {shaders::common_glsl, shaders::draw_frag}, def)});
    p.flush = gl::link_program(gl, {gl::shader_stage(GL_VERTEX_SHADER, {shaders::flush_vert}),
                                    gl::shader_stage(GL_FRAGMENT_SHADER, {shaders::common_glsl, shaders::flush_frag}, def)});
  } catch (const gl::ShaderError& e) {
    throw GlUnavailable(std::string("GL k-buffer: ") + e.what());
  }
  p.mvp = gl.glGetUniformLocation(p.draw, "mvp");
  p.nrows = gl.glGetUniformLocation(p.draw, "nrows");
  gl.check("program creation");
  return programs[k] = p;
}

void GlKBuffer::Impl::ensure_targets(int w, int h, int k) {
  if (w != tex_w || h != tex_h || k != tex_k) {
    if (tex_entries) {
      const GLuint t[3] = {tex_entries, tex_accum, tex_state};
      gl.glDeleteTextures(3, t);
    }
    gl.glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &tex_entries);
    gl.glTextureStorage3D(tex_entries, 1, GL_RGBA32UI, w, h, k);
    gl.glCreateTextures(GL_TEXTURE_2D, 1, &tex_accum);
    gl.glTextureStorage2D(tex_accum, 1, GL_RGBA32F, w, h);
    gl.glCreateTextures(GL_TEXTURE_2D, 1, &tex_state);
    gl.glTextureStorage2D(tex_state, 1, GL_R32UI, w, h);
    tex_w = w, tex_h = h, tex_k = k;
    gl.check("image allocation");
  }
  if (w != fbo_w || h != fbo_h) {
    if (fbo) gl.glDeleteFramebuffers(1, &fbo);
    gl.glCreateFramebuffers(1, &fbo);
    gl.glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, w);
    gl.glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, h);
    if (gl.glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw GlUnavailable("GL k-buffer: a framebuffer without attachments is not complete");
    fbo_w = w, fbo_h = h;
  }
}

}  // namespace vob::havs
