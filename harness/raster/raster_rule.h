// The sampling rule of the harness rasterizer (`--raster exact|gl`).
//
// exact (default): edge functions of the unsnapped geometry in doubles at the pixel (or
// sample) centres, top-left rule for exact zeros (polygon_raster.h); depths are the ray
// parameter in doubles, equal depths are ties (oracle.h).
//
// gl: what llvmpipe (Mesa's gallium software rasterizer, which OSMesa is here; Mesa 22.3,
// lp_setup_tri.c) draws into a framebuffer object, pixel centres only (S = 1):
// - window coordinates (SampleFrame::project: x, y in pixels, row 0 at the bottom, y up,
//   as in a GL framebuffer object) are snapped to 1/256 pixel after subtracting the pixel
//   offset 0.5: X = round-half-even((x - 0.5) * 256), the same for y; pixel (i, j) is then
//   the integer point (256 i, 256 j);
// - a triangle of zero fixed-point area covers nothing; otherwise, ordered so that its
//   fixed-point area dx01 * dy20 - dx20 * dy01 is positive, edge i (vertex i to i + 1) has
//   dcdx = y_i - y_i+1, dcdy = x_i - x_i+1 and E_i(X, Y) = dcdx (x_i - X) - dcdy (y_i - Y),
//   exact in 64-bit integers; pixel (X, Y) is covered when E_i > 0 for every edge, or
//   E_i == 0 on an edge the fill rule owns: dcdx < 0, or dcdx == 0 and dcdy > 0
//   (llvmpipe's bottom_edge_rule 0, which Mesa uses for framebuffer objects: D3D's top-left
//   rule in a y-down frame, so left edges and the edges at the bottom in GL's y-up window);
// - within llvmpipe's bounding box: x in [min X >> 8, (max X - 1) >> 8], y likewise;
// - depth as llvmpipe's depth test compares it: the vertices' window depth z in [0, 1]
//   (gl_depth_range below), interpolated as llvmpipe's float setup and fragment code do it
//   (llvmpipe_depth.h, checked bit for bit against its depth buffer) and converted to 24
//   bits; fragments of equal 24-bit depth are ties. (Cells composite without a depth test:
//   their segments are in doubles on the snapped planes, cell_raster_gl.h.)
// The rule describes llvmpipe given those window coordinates: the GL backends hand
// llvmpipe the snapped coordinates themselves (harness/gl/window_vertices.h), so its own
// float vertex transform does not enter. Those float depths can order two triangles one
// way at one pixel and the other way at another; the oracle then tells violations every
// order has from the others (harness/oracle/rule_cycles.h). Other GL implementations snap to other grids (most desktop
// GPUs also use 8 subpixel bits, some 4) and may own other edges; the rule is llvmpipe's.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>

#include "harness/geometry/vec3.h"
#include "harness/view/camera.h"

namespace vob {

enum class RasterRule { exact, gl };

inline const char* raster_rule_name(RasterRule r) { return r == RasterRule::gl ? "gl" : "exact"; }
// "exact" or "gl"; InputError naming `who` otherwise.
RasterRule parse_raster_rule(const std::string& name, const std::string& who);

constexpr int kGlSubpixelBits = 8;             // llvmpipe's FIXED_ORDER
constexpr int64_t kGlSubpixels = 1 << kGlSubpixelBits;
constexpr double kGlDepthMax = 16777215.0;     // 2^24 - 1: a 24-bit depth buffer

// The window coordinates the rule describes: |x - 0.5| below 2^22 pixels, where the edge
// functions' products of fixed-point coordinates fit in 64 bits and llvmpipe sets a
// triangle up without clipping it first. A vertex beyond (next to the eye plane: an eye
// inside or beside the model) belongs to a triangle GL clips, which the rule does not
// describe; before this bound its snapped coordinate overflowed (UBSan, eye-inside).
constexpr double kGlMaxWindow = 4194304.0;
[[noreturn]] void throw_beyond_gl_range(double window);

// Window coordinate -> llvmpipe's fixed-point coordinate; InputError beyond kGlMaxWindow.
inline int64_t gl_snap(double window) {
  if (!(std::fabs(window - 0.5) < kGlMaxWindow)) throw_beyond_gl_range(window);
  return static_cast<int64_t>(std::nearbyint((window - 0.5) * double(kGlSubpixels)));
}
// The window coordinate that snaps to X exactly, and which llvmpipe's float arithmetic
// (x - 0.5f) * 256 reproduces without rounding (|X| < 2^23).
inline double gl_unsnap(int64_t fixed) { return double(fixed) / double(kGlSubpixels) + 0.5; }

// Near and far planes (view depths) of the GL backends, around the bounding sphere of what
// they draw (centre, radius): nothing drawn is clipped by them.
struct GlDepthRange {
  double near = 0, far = 1;
};
GlDepthRange gl_depth_range(const Camera& view, const Vec3& centre, double radius);

// Window depth in [0, 1] of view depth zc (along forward from the eye) under that range,
// as GL's projection and glDepthRange(0, 1) map it; and its 24-bit buffer value.
double gl_window_depth(const Camera& view, const GlDepthRange& r, double zc);
inline int64_t gl_depth24(double z) {
  return static_cast<int64_t>(std::nearbyint(std::fmin(std::fmax(z, 0.0), 1.0) * kGlDepthMax));
}

}  // namespace vob
