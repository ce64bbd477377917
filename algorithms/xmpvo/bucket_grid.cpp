#include "algorithms/xmpvo/bucket_grid.h"

namespace vob::xmpvo {

void BucketGrid::fit(const Box& all, double slack, size_t items) {
  const double w = std::max(all.x1 - all.x0, 0.0), h = std::max(all.y1 - all.y0, 0.0);
  const double target = std::max<double>(1.0, static_cast<double>(items));
  // A degenerate extent still gets a positive aspect ratio.
  const double ww = std::max(w, 1e-12 * (w + h) + 1e-300), hh = std::max(h, 1e-12 * (w + h) + 1e-300);
  gw = static_cast<int>(std::clamp(std::sqrt(target * ww / hh), 1.0, 16384.0));
  gh = static_cast<int>(std::clamp(target / gw, 1.0, 16384.0));
  gx0 = all.x0 - slack;
  gy0 = all.y0 - slack;
  cw = (w + 2 * slack) / gw;
  ch = (h + 2 * slack) / gh;
}

}  // namespace vob::xmpvo
