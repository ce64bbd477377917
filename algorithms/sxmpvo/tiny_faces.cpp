#include "algorithms/sxmpvo/tiny_faces.h"

#include <algorithm>

namespace vob::sxmpvo {

BoxKind sample_box(const SampleFrame& frame, const ProjectedVertex* q, int n, SampleRect& box) {
  double lx = 0, hx = 0, ly = 0, hy = 0;
  for (int i = 0; i < n; ++i) {
    if (!q[i].in_front) return BoxKind::Large;
    const double x = q[i].x, y = q[i].y;
    if (i == 0 || x < lx) lx = x;
    if (i == 0 || x > hx) hx = x;
    if (i == 0 || y < ly) ly = y;
    if (i == 0 || y > hy) hy = y;
  }
  // PolygonRaster::may_cover_a_sample's margin and rounding: sample (sx, sy) has its centre
  // at (sx + 0.5, sy + 0.5), and a face with no centre in this box is rejected there too.
  const double m = 1e-6 * (1.0 + std::max({std::fabs(lx), std::fabs(hx), std::fabs(ly), std::fabs(hy)}));
  const double x0 = std::ceil(lx - m - 0.5), x1 = std::floor(hx + m - 0.5);
  const double y0 = std::ceil(ly - m - 0.5), y1 = std::floor(hy + m - 0.5);
  if (!(x0 <= x1 && y0 <= y1 && x1 >= 0 && y1 >= 0 && x0 < frame.cols() && y0 < frame.rows()))
    return BoxKind::None;
  box = SampleRect{static_cast<int>(std::max(x0, 0.0)), static_cast<int>(std::max(y0, 0.0)),
                   static_cast<int>(std::min(x1, frame.cols() - 1.0)),
                   static_cast<int>(std::min(y1, frame.rows() - 1.0))};
  const int64_t samples = int64_t(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  return samples <= kTinyMaxSamples ? BoxKind::Tiny : BoxKind::Large;
}

}  // namespace vob::sxmpvo
