// havs_gl_probe: what an OSMesa (llvmpipe) context offers the GPU k-buffer of HAVS section 4.
// Creates a 4.5 core context with OSMesaCreateContextAttribs, loads functions with
// OSMesaGetProcAddress, and prints the version, renderer and whether the extensions the
// k-buffer shader needs are present: image load/store (the k entries as images) and
// fragment-shader interlock (without it the read-modify-write of Fig. 5 races).
// Kept apart from the vobench binary: it links OSMesa and no VTK OpenGL module.
#include <GL/osmesa.h>
#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <vector>

int main() {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                         OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) {
    std::printf("OSMesaCreateContextAttribs(4.5 core) failed\n");
    return 1;
  }
  std::vector<unsigned char> buf(64 * 64 * 4);
  if (!OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 64, 64)) {
    std::printf("OSMesaMakeCurrent failed\n");
    return 1;
  }
  auto get_string = reinterpret_cast<PFNGLGETSTRINGPROC>(OSMesaGetProcAddress("glGetString"));
  auto get_stringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(OSMesaGetProcAddress("glGetStringi"));
  auto get_integerv = reinterpret_cast<PFNGLGETINTEGERVPROC>(OSMesaGetProcAddress("glGetIntegerv"));
  std::printf("GL_VERSION  %s\nGL_RENDERER %s\nGLSL        %s\n",
              reinterpret_cast<const char*>(get_string(GL_VERSION)),
              reinterpret_cast<const char*>(get_string(GL_RENDERER)),
              reinterpret_cast<const char*>(get_string(GL_SHADING_LANGUAGE_VERSION)));
  GLint n = 0;
  get_integerv(GL_NUM_EXTENSIONS, &n);
  const char* wanted[] = {"GL_ARB_shader_image_load_store", "GL_ARB_fragment_shader_interlock",
                          "GL_INTEL_fragment_shader_ordering", "GL_NV_fragment_shader_interlock",
                          "GL_ARB_shader_atomic_counters"};
  for (const char* w : wanted) {
    bool found = false;
    for (GLint i = 0; i < n; ++i)
      if (std::strcmp(reinterpret_cast<const char*>(get_stringi(GL_EXTENSIONS, i)), w) == 0) found = true;
    std::printf("%-36s %s\n", w, found ? "yes" : "no");
  }
  GLint units = 0;
  get_integerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &units);
  std::printf("GL_MAX_FRAGMENT_IMAGE_UNIFORMS %d\n", units);
  OSMesaDestroyContext(ctx);
  return 0;
}
