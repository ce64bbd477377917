// The GL k-buffer's shaders, files in shaders/ embedded at build time
// (vob_embed_shaders in CMakeLists.txt).
#pragma once
#include "harness/gl/shader_program.h"

namespace vob::havs::shaders {
extern const gl::ShaderFile common_glsl;  // definitions of the draw and flush passes
extern const gl::ShaderFile draw_vert;
extern const gl::ShaderFile draw_frag;
extern const gl::ShaderFile flush_vert;
extern const gl::ShaderFile flush_frag;
}  // namespace vob::havs::shaders
