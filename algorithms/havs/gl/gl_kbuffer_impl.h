// GlKBuffer's state (gl_kbuffer.h): the context and its GL functions, the uploaded faces,
// the images and programs. Set up in gl_kbuffer_setup.cpp, used by gl_kbuffer.cpp.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "algorithms/havs/gl/gl_kbuffer.h"
#include "harness/gl/gl_functions.h"
#include "harness/gl/osmesa_context.h"

namespace vob::havs {

struct GlKBuffer::Impl {
  gl::OsmesaContext ctx;
  gl::Functions gl{ctx};

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
  const Programs& programs_for(int k);
  void ensure_targets(int w, int h, int k);
};

}  // namespace vob::havs
