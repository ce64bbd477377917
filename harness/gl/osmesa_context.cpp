#include "harness/gl/osmesa_context.h"

#include <GL/osmesa.h>
#include <GL/glcorearb.h>
#include <dlfcn.h>

#include <cstring>
#include <mutex>
#include <stdexcept>

namespace vob::gl {
namespace {

// libOSMesa is opened on the first context, not linked: linked, it and Mesa's LLVM
// (libLLVM-15, 117 MB, half a million relocations) were loaded and relocated by every
// vobench process, most of which never make a GL context.
struct OsmesaApi {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

const OsmesaApi& osmesa() {
  static std::once_flag once;
  static OsmesaApi api;
  static std::string error;
  std::call_once(once, [] {
    void* lib = dlopen(VOB_OSMESA_SONAME, RTLD_LAZY | RTLD_LOCAL);
    if (!lib) {
      const char* why = dlerror();
      error = std::string("OSMesa: cannot load " VOB_OSMESA_SONAME " (") + (why ? why : "unknown") + ")";
      return;
    }
    auto sym = [&](const char* name) {
      void* f = dlsym(lib, name);
      if (!f && error.empty()) error = std::string("OSMesa: " VOB_OSMESA_SONAME " has no ") + name;
      return f;
    };
    api.create_context_attribs = reinterpret_cast<decltype(api.create_context_attribs)>(sym("OSMesaCreateContextAttribs"));
    api.destroy_context = reinterpret_cast<decltype(api.destroy_context)>(sym("OSMesaDestroyContext"));
    api.make_current = reinterpret_cast<decltype(api.make_current)>(sym("OSMesaMakeCurrent"));
    api.get_proc_address = reinterpret_cast<decltype(api.get_proc_address)>(sym("OSMesaGetProcAddress"));
  });
  if (!error.empty()) throw std::runtime_error(error);
  return api;
}

}  // namespace

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
  context_ = osmesa().create_context_attribs(attribs.data(), nullptr);
  if (!context_)
    throw std::runtime_error("OSMesa: cannot create a GL " + std::to_string(request.major) + "." +
                             std::to_string(request.minor) +
                             (request.core_profile ? " core" : " compatibility") + " context");
  colour_.assign(size_t(request.width) * request.height * 4, 0);
  make_current();
}

OsmesaContext::~OsmesaContext() {
  if (context_) osmesa().destroy_context(static_cast<OSMesaContext>(context_));
}

void OsmesaContext::make_current() {
  if (!osmesa().make_current(static_cast<OSMesaContext>(context_), colour_.data(), GL_UNSIGNED_BYTE,
                         request_.width, request_.height))
    throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
}

void* OsmesaContext::proc_address(const char* name) const {
  void* fn = reinterpret_cast<void*>(osmesa().get_proc_address(name));
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
