// havs_gl_probe: what an OSMesa (llvmpipe) context offers the GPU k-buffer of HAVS section 4.
// Creates the harness' 4.5 core context (harness/gl/osmesa_context.h) and prints the version,
// renderer and whether the extensions the k-buffer shader needs are present: image
// load/store (the k entries as images) and fragment-shader interlock (without it the
// read-modify-write of Fig. 5 may race). Exit 1 with one line when there is no context.
#include <GL/glcorearb.h>

#include <cstdio>
#include <stdexcept>

#include "harness/gl/osmesa_context.h"

int main() {
  try {
    vob::gl::ContextRequest req;
    req.width = req.height = 64;
    vob::gl::OsmesaContext ctx(req);
    auto get_string = ctx.load<PFNGLGETSTRINGPROC>("glGetString");
    auto get_integerv = ctx.load<PFNGLGETINTEGERVPROC>("glGetIntegerv");
    std::printf("GL_VERSION  %s\nGL_RENDERER %s\nGLSL        %s\n", ctx.version().c_str(),
                ctx.renderer().c_str(),
                reinterpret_cast<const char*>(get_string(GL_SHADING_LANGUAGE_VERSION)));
    for (const char* w : {"GL_ARB_shader_image_load_store", "GL_ARB_fragment_shader_interlock",
                          "GL_INTEL_fragment_shader_ordering", "GL_NV_fragment_shader_interlock",
                          "GL_ARB_shader_atomic_counters", "GL_ARB_gpu_shader_fp64",
                          "GL_ARB_framebuffer_no_attachments"})
      std::printf("%-36s %s\n", w, ctx.has_extension(w) ? "yes" : "no");
    GLint units = 0;
    get_integerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &units);
    std::printf("GL_MAX_FRAGMENT_IMAGE_UNIFORMS %d\n", units);
    return 0;
  } catch (const std::exception& e) {
    std::printf("no GL context: %s\n", e.what());
    return 1;
  }
}
