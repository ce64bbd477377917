// Shader errors name the shader files with their line ranges and carry the driver's log,
// whose line numbers the inserted #defines do not shift (harness/gl/shader_program.h).
// Skipped without OSMesa.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "harness/gl/shader_program.h"

using namespace vob;

namespace {

std::unique_ptr<gl::OsmesaContext> context() {
  try {
    return std::make_unique<gl::OsmesaContext>(gl::ContextRequest{16, 16, 3, 3, true, 0, 0});
  } catch (const std::runtime_error&) {
    return nullptr;
  }
}

const gl::ShaderFile kVertex{"tests/ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n"};
const gl::ShaderFile kCommon{"tests/common.glsl", "#version 330 core\nout vec4 colour;\n"};
const gl::ShaderFile kBroken{"tests/broken.frag", "void f() {}\nvoid main() { colour = vec4(undefined_name); }\n"};

std::string link_error(const gl::Functions& f, const std::vector<gl::ShaderFile>& fragment) {
  try {
    const GLuint p = gl::link_program(f, {gl::shader_stage(GL_VERTEX_SHADER, {kVertex}),
                                          gl::shader_stage(GL_FRAGMENT_SHADER, fragment, "#define K 4\n")});
    f.glDeleteProgram(p);
  } catch (const gl::ShaderError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ShaderProgram, CompileErrorNamesTheFileAndTheLine) {
  const auto ctx = context();
  if (!ctx) GTEST_SKIP() << "no OSMesa GL 3.3 core context";
  const gl::Functions f(*ctx);
  const std::string e = link_error(f, {kCommon, kBroken});
  EXPECT_NE(e.find("tests/common.glsl (lines 1-2) + tests/broken.frag (lines 3-4)"), std::string::npos) << e;
  EXPECT_NE(e.find("undefined_name"), std::string::npos) << e;
  // Line 2 of broken.frag is line 4 of the stage: the #define did not shift it.
  EXPECT_NE(e.find(":4("), std::string::npos) << e;
}

TEST(ShaderProgram, FilesThatCompileLink) {
  const auto ctx = context();
  if (!ctx) GTEST_SKIP() << "no OSMesa GL 3.3 core context";
  const gl::Functions f(*ctx);
  const gl::ShaderFile fine{"tests/fine.frag", "void main() { colour = vec4(float(K)); }\n"};
  EXPECT_EQ(link_error(f, {kCommon, fine}), "");
}
