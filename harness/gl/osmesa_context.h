// An offscreen OpenGL context on OSMesa (Mesa's llvmpipe), for the plugins that run real
// OpenGL (stencil layering, the HAVS shader k-buffer). GL functions are loaded through
// OSMesaGetProcAddress rather than linked, so the vobench binary exports no gl* symbols
// that could clash with another GL library in the process.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vob::gl {

struct ContextRequest {
  int width = 512, height = 512;
  int major = 4, minor = 5;  // 0.0 asks for OSMesa's default (compatibility) context
  bool core_profile = true;
  int depth_bits = 24, stencil_bits = 8;
};

class OsmesaContext {
 public:
  // Creates the context and makes it current on this thread with an RGBA8 colour buffer
  // of the requested size. Throws std::runtime_error naming what failed.
  explicit OsmesaContext(const ContextRequest& request);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // Makes the context current again (after another context was used on this thread).
  void make_current();
  // A GL entry point, or std::runtime_error when OSMesa does not have it.
  template <class Fn>
  Fn load(const char* name) const { return reinterpret_cast<Fn>(proc_address(name)); }

  int width() const { return request_.width; }
  int height() const { return request_.height; }
  std::string version() const;   // GL_VERSION
  std::string renderer() const;  // GL_RENDERER
  bool has_extension(const std::string& name) const;

 private:
  void* proc_address(const char* name) const;
  ContextRequest request_;
  void* context_ = nullptr;  // OSMesaContext
  std::vector<unsigned char> colour_;
};

}  // namespace vob::gl
