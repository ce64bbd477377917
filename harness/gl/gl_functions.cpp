#include "harness/gl/gl_functions.h"

#include <cstdio>
#include <stdexcept>

namespace vob::gl {

Functions::Functions(const OsmesaContext& ctx) {
#define VOB_GL_LOAD(type, name) name = ctx.load<type>(#name);
  VOB_GL_FUNCTIONS(VOB_GL_LOAD)
#undef VOB_GL_LOAD
}

void Functions::check(const char* what) const {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", unsigned(e));
  throw std::runtime_error(std::string("GL error ") + buf + " in " + what);
}

}  // namespace vob::gl
