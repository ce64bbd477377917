#include "algorithms/sxmpvo/tiny_faces.h"

#include <algorithm>

#include "harness/raster/sample_centres.h"

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
  // The samples PolygonRaster::may_cover_a_sample would let through (the same function).
  if (!sample_centres_in(frame, lx, hx, ly, hy, box)) return BoxKind::None;
  const int64_t samples = int64_t(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  return samples <= kTinyMaxSamples ? BoxKind::Tiny : BoxKind::Large;
}

}  // namespace vob::sxmpvo
