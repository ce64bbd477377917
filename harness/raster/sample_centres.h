// The sample centres a polygon's projected bounding box may hold, with the rasterizer's
// rounding margin: PolygonRaster rejects a polygon on exactly this test, and SXMPVO's
// tiny-face path scans exactly these samples, so both must compute it the same way.
#pragma once
#include <algorithm>
#include <cmath>

#include "harness/raster/sample_frame.h"

namespace vob {

// Samples whose centres (sx + 0.5, sy + 0.5) lie in [lx, hx] x [ly, hy] widened by a relative
// 1e-6, clipped to the frame; false when there is none.
inline bool sample_centres_in(const SampleFrame& frame, double lx, double hx, double ly, double hy,
                              SampleRect& out) {
  const double m = 1e-6 * (1.0 + std::max({std::fabs(lx), std::fabs(hx), std::fabs(ly), std::fabs(hy)}));
  const double x0 = std::ceil(lx - m - 0.5), x1 = std::floor(hx + m - 0.5);
  const double y0 = std::ceil(ly - m - 0.5), y1 = std::floor(hy + m - 0.5);
  if (!(x0 <= x1 && y0 <= y1 && x1 >= 0 && y1 >= 0 && x0 < frame.cols() && y0 < frame.rows())) return false;
  out = SampleRect{static_cast<int>(std::max(x0, 0.0)), static_cast<int>(std::max(y0, 0.0)),
                   static_cast<int>(std::min(x1, frame.cols() - 1.0)),
                   static_cast<int>(std::min(y1, frame.rows() - 1.0))};
  return true;
}

}  // namespace vob
