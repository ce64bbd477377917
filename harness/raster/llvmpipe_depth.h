// llvmpipe's fragment depth as it computes it (Mesa 22.3; the gl sampling rule's depth,
// raster_rule.h), in the same float operations in the same order:
// - the vertex's window z is the float viewport transform of its NDC z: z * 0.5f + 0.5f
//   (draw's viewport stage, glDepthRange(0, 1));
// - the triangle setup function (lp_state_setup.c: init_args, calc_coef4), given the
//   vertices in the order triangle setup hands them over (counter-clockwise in llvmpipe's
//   fixed-point sense: v1, v0, v2 when the fixed-point area is negative), computes in
//   floats, without fused operations: ooa = 1 / (dx01 dy20 - dy01 dx20), the gradients
//   dzdx = dz01 (dy20 ooa) - dz20 (dy01 ooa), dzdy = dz20 (dx01 ooa) - dz01 (dx20 ooa), and
//   the plane's value at pixel (0, 0): a0 = z0 - (dzdx (x0 - 0.5) + dzdy (y0 - 0.5));
// - the fragment shader (lp_bld_interp.c: interp_attrib_linear) evaluates
//   fma(dzdy, y, fma(dzdx, x, a0)) at integer pixel (x, y): llvm.fmuladd, which LLVM fuses
//   on CPUs with FMA (this one; tests/harness/gl/llvmpipe_depth_test.cpp checks it against
//   llvmpipe's depth buffer bit for bit);
// - the depth test (lp_bld_depth.c, lp_build_clamped_float_to_unsigned_norm with 24 bits)
//   compares round-half-even(float(z * 16777215)), z clamped to [0, 1].
// The plane's value at the origin is where the precision goes: on a steep triangle far
// from it a0 is large and its rounding is tens of 24-bit steps at the pixel (the source's
// own note in calc_coef4 says as much), which a plane evaluated in doubles does not reproduce.
#pragma once
#include <cstdint>

namespace vob {

struct LlvmpipeDepthPlane {
  float a0 = 0, dzdx = 0, dzdy = 0;
};

// The window z llvmpipe interpolates for a vertex of window depth `window_depth` in [0, 1]
// handed over as NDC float(2 window_depth - 1) (harness/gl/window_vertices.h).
float llvmpipe_window_z(double window_depth);

// The setup's plane of the triangle with float window positions (x[i], y[i], z[i]), given
// in the order llvmpipe's setup receives them.
LlvmpipeDepthPlane llvmpipe_depth_plane(const float x[3], const float y[3], const float z[3]);

// The 24-bit value the depth test compares at pixel (px, py).
int64_t llvmpipe_depth24(const LlvmpipeDepthPlane& p, int px, int py);

}  // namespace vob
