#include "harness/gl/shader_program.h"

#include <algorithm>

namespace vob::gl {
namespace {

// The driver's log of a shader or program (glGetShaderInfoLog / glGetProgramInfoLog).
template <class GetLog>
std::string info_log(GetLog get, GLuint id) {
  char log[4096] = {0};
  get(id, sizeof log, nullptr, log);
  return log;
}

GLuint compile(const Functions& gl, const ShaderStage& stage) {
  std::vector<const char*> src;
  for (const std::string& p : stage.parts) src.push_back(p.c_str());
  const GLuint s = gl.glCreateShader(stage.type);
  gl.glShaderSource(s, GLsizei(src.size()), src.data(), nullptr);
  gl.glCompileShader(s);
  GLint ok = 0;
  gl.glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(gl.glGetShaderInfoLog, s);
    gl.glDeleteShader(s);
    throw ShaderError("shader " + stage.name + " does not compile: " + log);
  }
  return s;
}

}  // namespace

ShaderStage shader_stage(GLenum type, const std::vector<ShaderFile>& files,
                         const std::string& defines) {
  ShaderStage st{type, "", {}};
  int line = 1;  // where the next file starts in the concatenated source
  for (size_t i = 0; i < files.size(); ++i) {
    std::string text(files[i].text);
    if (!text.empty() && text.back() != '\n') text += '\n';
    const int lines = int(std::count(text.begin(), text.end(), '\n'));
    if (files.size() > 1)
      st.name += (i ? " + " : "") + std::string(files[i].path) + " (lines " + std::to_string(line) +
                 "-" + std::to_string(line + lines - 1) + ")";
    else
      st.name = files[i].path;
    if (i == 0) {
      // GLSL wants #version first: the defines go after its line, then "#line" restores
      // the numbering so that the defines do not shift it.
      const size_t v = text.find("#version");
      const size_t eol = v == std::string::npos ? 0 : text.find('\n', v) + 1;
      const int next = int(std::count(text.begin(), text.begin() + eol, '\n')) + 1;
      st.parts.push_back(text.substr(0, eol));
      st.parts.push_back(defines + "#line " + std::to_string(next) + "\n");
      st.parts.push_back(text.substr(eol));
    } else {
      st.parts.push_back(std::move(text));
    }
    line += lines;
  }
  return st;
}

GLuint link_program(const Functions& gl, const std::vector<ShaderStage>& stages) {
  std::vector<GLuint> shaders;
  std::string names;
  try {
    for (const ShaderStage& st : stages) {
      shaders.push_back(compile(gl, st));
      names += (names.empty() ? "" : " + ") + st.name;
    }
  } catch (...) {
    for (GLuint s : shaders) gl.glDeleteShader(s);
    throw;
  }
  const GLuint p = gl.glCreateProgram();
  for (GLuint s : shaders) gl.glAttachShader(p, s);
  gl.glLinkProgram(p);
  for (GLuint s : shaders) gl.glDeleteShader(s);
  GLint ok = 0;
  gl.glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(gl.glGetProgramInfoLog, p);
    gl.glDeleteProgram(p);
    throw ShaderError("program " + names + " does not link: " + log);
  }
  return p;
}

}  // namespace vob::gl
