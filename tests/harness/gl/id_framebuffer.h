// Test helper for comparing llvmpipe with the harness's raster rules pixel by pixel:
// triangles with ids drawn into an item buffer (R32UI, a shader writes id + 1) beside a
// DEPTH24_STENCIL8 buffer, then read back. The test sets the depth and stencil state it
// needs between construction and draw().
#pragma once

#include <cstdint>
#include <vector>

#include "harness/gl/osmesa_context.h"
#include "harness/gl/shader_program.h"
#include "harness/gl/window_vertices.h"

namespace vob::test {

// The llvmpipe context (OSMesa, GL 3.3 core, 24-bit depth, 8-bit stencil) these tests draw
// with, made on first use and shared by them; made current again on every call, since
// other tests in the binary make contexts of their own. Throws without OSMesa.
inline gl::Functions& llvmpipe() {
  static gl::OsmesaContext ctx(gl::ContextRequest{16, 16, 3, 3, true, 24, 8});
  static gl::Functions f(ctx);
  ctx.make_current();
  return f;
}

// The vertices of `tris` for IdFramebuffer: each corner's window position (t.x[k], t.y[k])
// in the NDC of `vp`, made into a Vertex by make(ndc, triangle index, corner).
template <class Vertex, class Tri, class Make>
std::vector<Vertex> triangle_vertices(const std::vector<Tri>& tris, const gl::Pow2Viewport& vp, Make&& make) {
  std::vector<Vertex> v;
  v.reserve(tris.size() * 3);
  for (size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) v.push_back(make(vp.ndc(tris[t].x[k], tris[t].y[k]), t, k));
  return v;
}

class IdFramebuffer {
 public:
  // Uploads `vertices` (attribute 0: `dims` floats at the start of each vertex, attribute 1:
  // the uint32_t id right after them) and binds a w x h framebuffer, a viewport of
  // vw x vh (gl::Pow2Viewport's, which may reach past the framebuffer) and `program`, both
  // buffers cleared (items 0, depth 1, stencil 0).
  template <class Vertex>
  IdFramebuffer(gl::Functions& f, GLuint program, int w, int h, int vw, int vh,
                const std::vector<Vertex>& vertices, int dims)
      : f_(f), w_(w), h_(h), count_(GLsizei(vertices.size())) {
    f.glGenVertexArrays(1, &vao_);
    f.glBindVertexArray(vao_);
    f.glGenBuffers(1, &vbo_);
    f.glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    f.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                   GL_STREAM_DRAW);
    f.glVertexAttribPointer(0, dims, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    f.glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Vertex),
                             reinterpret_cast<const void*>(dims * sizeof(float)));
    f.glEnableVertexAttribArray(0);
    f.glEnableVertexAttribArray(1);
    f.glGenFramebuffers(1, &fbo_);
    f.glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    f.glGenRenderbuffers(2, rb_);
    f.glBindRenderbuffer(GL_RENDERBUFFER, rb_[0]);
    f.glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, w, h);
    f.glBindRenderbuffer(GL_RENDERBUFFER, rb_[1]);
    f.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    f.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb_[0]);
    f.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb_[1]);
    complete_ = f.glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    f.glDrawBuffers(1, &buf);
    f.glReadBuffer(GL_COLOR_ATTACHMENT0);
    f.glViewport(0, 0, vw, vh);
    f.glDisable(GL_CULL_FACE);
    f.glDepthMask(GL_TRUE);
    f.glStencilMask(~0u);
    const GLuint zero[4] = {0, 0, 0, 0};
    f.glClearBufferuiv(GL_COLOR, 0, zero);
    f.glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
    f.glUseProgram(program);
  }
  ~IdFramebuffer() {
    f_.glDeleteRenderbuffers(2, rb_);
    f_.glDeleteFramebuffers(1, &fbo_);
    f_.glDeleteBuffers(1, &vbo_);
    f_.glDeleteVertexArrays(1, &vao_);
  }
  IdFramebuffer(const IdFramebuffer&) = delete;
  IdFramebuffer& operator=(const IdFramebuffer&) = delete;

  bool complete() const { return complete_; }
  void draw() { f_.glDrawArrays(GL_TRIANGLES, 0, count_); }

  // The framebuffer read back, row by row from the bottom.
  std::vector<uint32_t> read_items() { return read<uint32_t>(GL_RED_INTEGER, GL_UNSIGNED_INT); }
  std::vector<uint8_t> read_stencil() { return read<uint8_t>(GL_STENCIL_INDEX, GL_UNSIGNED_BYTE); }
  // 24-bit depth values (the top 24 bits of DEPTH24_STENCIL8).
  std::vector<uint32_t> read_depth24() {
    auto d = read<uint32_t>(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
    for (uint32_t& v : d) v >>= 8;
    return d;
  }

 private:
  template <class T>
  std::vector<T> read(GLenum format, GLenum type) {
    std::vector<T> out(size_t(w_) * h_, 0);
    f_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    f_.glReadPixels(0, 0, w_, h_, format, type, out.data());
    return out;
  }

  gl::Functions& f_;
  int w_, h_;
  GLsizei count_;
  GLuint vao_ = 0, vbo_ = 0, fbo_ = 0, rb_[2] = {0, 0};
  bool complete_ = false;
};

}  // namespace vob::test
