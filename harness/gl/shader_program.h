// GLSL programs from shader files embedded at build time (cmake/EmbedShaders.cmake):
// compile and link errors name the shader file and carry the driver's log.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/gl/gl_functions.h"

namespace vob::gl {

// A shader file as embedded by vob_embed_shaders(): its path in the source tree and text.
struct ShaderFile {
  const char* path;
  const char* text;
};

// One stage: its type and the texts concatenated into it; `name` is what errors call it.
struct ShaderStage {
  GLenum type;
  std::string name;
  std::vector<std::string> parts;
};

struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Compiles and links the stages into a program; ShaderError ("shader FILE does not
// compile: LOG", "program FILE + FILE does not link: LOG") otherwise.
GLuint link_program(const Functions& gl, const std::vector<ShaderStage>& stages);

// The files' texts in order, `defines` (e.g. "#define K 8\n") inserted after the first
// one's #version line without shifting the line numbers. The stage's name lists each file
// with its line range in the concatenation, so that a log line "0:L" (Mesa reports no
// source-string number) can be traced to its file.
ShaderStage shader_stage(GLenum type, const std::vector<ShaderFile>& files,
                         const std::string& defines = "");

}  // namespace vob::gl
