// Compiled with -ffp-contract=off (CMakeLists.txt): the setup's multiplies and subtractions
// are separate roundings in llvmpipe, and only the interpolation's fmuladd is fused.
#include "harness/raster/llvmpipe_depth.h"

#include <algorithm>
#include <cmath>

namespace vob {

float llvmpipe_window_z(double window_depth) {
  const float ndc = float(2 * window_depth - 1);
  return ndc * 0.5f + 0.5f;  // exact product: one rounding, fused or not
}

LlvmpipeDepthPlane llvmpipe_depth_plane(const float x[3], const float y[3], const float z[3]) {
  const float dx01 = x[0] - x[1], dy01 = y[0] - y[1], dz01 = z[0] - z[1];
  const float dx20 = x[2] - x[0], dy20 = y[2] - y[0], dz20 = z[2] - z[0];
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  const float dx20o = dx20 * ooa, dy20o = dy20 * ooa, dx01o = dx01 * ooa, dy01o = dy01 * ooa;
  LlvmpipeDepthPlane p;
  const float gx0 = dz01 * dy20o, gx1 = dz20 * dy01o;
  p.dzdx = gx0 - gx1;
  const float gy0 = dz20 * dx01o, gy1 = dz01 * dx20o;
  p.dzdy = gy0 - gy1;
  const float x0c = x[0] - 0.5f, y0c = y[0] - 0.5f;
  const float sx = p.dzdx * x0c, sy = p.dzdy * y0c;
  const float s = sx + sy;
  p.a0 = z[0] - s;
  return p;
}

int64_t llvmpipe_depth24(const LlvmpipeDepthPlane& p, int px, int py) {
  float z = std::fma(p.dzdy, float(py), std::fma(p.dzdx, float(px), p.a0));
  z = std::clamp(z, 0.0f, 1.0f);
  const float scaled = z * 16777215.0f;
  return static_cast<int64_t>(std::nearbyint(scaled));
}

}  // namespace vob
