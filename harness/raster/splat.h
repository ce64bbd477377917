// Voxel splats: the footprint of a voxel is every sample within r pixels of its projected
// centre, at depth Camera::depth(centre) (distance from the eye; orthographic: distance
// along the view direction). r is given, or the projected half-diagonal of the voxel
// (|spacing| / 2, i.e. spacing * sqrt(3) / 2 for cubic voxels) at the voxel's view depth.
// Voxels not in front of the eye (perspective) or behind the eye plane (orthographic) are
// not drawn.
#pragma once
#include "harness/raster/sample_frame.h"

namespace vob {

struct Splat {
  double cx = 0, cy = 0;  // projected centre, sample coordinates
  double radius = 0;      // in samples (pixels * S)
  double depth = 0;
  SampleRect box;         // samples whose centres may lie within the radius
};

// False when the voxel is not drawn. radius_px > 0 fixes the radius in pixels.
bool make_splat(const SampleFrame& frame, Vec3 centre, Vec3 spacing, double radius_px, Splat& out);

// Calls emit(sx, sy, q) for every sample of `clip` within the splat, where q = (distance /
// radius)^2 in [0, 1] (for footprint weights).
template <class Emit>
void scan_splat(const Splat& s, const SampleRect& clip, Emit&& emit) {
  const SampleRect r = s.box.intersect(clip);
  const double r2 = s.radius * s.radius;
  for (int sy = r.y0; sy <= r.y1; ++sy) {
    const double dy = sy + 0.5 - s.cy;
    for (int sx = r.x0; sx <= r.x1; ++sx) {
      const double dx = sx + 0.5 - s.cx;
      const double q = dx * dx + dy * dy;
      if (q <= r2) emit(sx, sy, q / r2);
    }
  }
}

}  // namespace vob
