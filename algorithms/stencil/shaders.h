// The GL layer backend's shaders, files in shaders/ embedded at build time
// (vob_embed_shaders in CMakeLists.txt).
#pragma once
#include "harness/gl/shader_program.h"

namespace vob::stencil::shaders {
extern const gl::ShaderFile item_vert;
extern const gl::ShaderFile item_frag;
}  // namespace vob::stencil::shaders
