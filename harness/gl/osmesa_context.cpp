#include "harness/gl/osmesa_context.h"

#include <GL/osmesa.h>
#include <GL/glcorearb.h>

#include <cstring>
#include <stdexcept>

namespace vob::gl {

OsmesaContext::OsmesaContext(const ContextRequest& request) : request_(request) {
  if (request.width <= 0 || request.height <= 0)
    throw std::runtime_error("OSMesa: impossible buffer size " + std::to_string(request.width) +
                             "x" + std::to_string(request.height));
  std::vector<int> attribs = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, request.depth_bits,
                              OSMESA_STENCIL_BITS, request.stencil_bits};
  if (request.major > 0) {
    attribs.insert(attribs.end(),
                   {OSMESA_PROFILE, request.core_profile ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
                    OSMESA_CONTEXT_MAJOR_VERSION, request.major, OSMESA_CONTEXT_MINOR_VERSION,
                    request.minor});
  }
  attribs.push_back(0);
  context_ = OSMesaCreateContextAttribs(attribs.data(), nullptr);
  if (!context_)
    throw std::runtime_error("OSMesa: cannot create a GL " + std::to_string(request.major) + "." +
                             std::to_string(request.minor) +
                             (request.core_profile ? " core" : " compatibility") + " context");
  colour_.assign(size_t(request.width) * request.height * 4, 0);
  make_current();
}

OsmesaContext::~OsmesaContext() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsmesaContext::make_current() {
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), colour_.data(), GL_UNSIGNED_BYTE,
                         request_.width, request_.height))
    throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
}

void* OsmesaContext::proc_address(const char* name) const {
  void* fn = reinterpret_cast<void*>(OSMesaGetProcAddress(name));
  if (!fn) throw std::runtime_error(std::string("OSMesa: no GL function ") + name);
  return fn;
}

std::string OsmesaContext::version() const {
  auto get_string = load<PFNGLGETSTRINGPROC>("glGetString");
  const auto* s = get_string(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string OsmesaContext::renderer() const {
  auto get_string = load<PFNGLGETSTRINGPROC>("glGetString");
  const auto* s = get_string(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "";
}

bool OsmesaContext::has_extension(const std::string& name) const {
  auto get_integerv = load<PFNGLGETINTEGERVPROC>("glGetIntegerv");
  auto get_stringi = load<PFNGLGETSTRINGIPROC>("glGetStringi");
  GLint n = 0;
  get_integerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i)
    if (name == reinterpret_cast<const char*>(get_stringi(GL_EXTENSIONS, GLuint(i)))) return true;
  return false;
}

}  // namespace vob::gl
