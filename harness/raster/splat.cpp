#include "harness/raster/splat.h"

namespace vob {

bool make_splat(const SampleFrame& frame, Vec3 centre, Vec3 spacing, double radius_px, Splat& out) {
  double zc;
  if (!frame.project(centre, out.cx, out.cy, zc)) return false;
  if (frame.ortho() && zc < 0) return false;
  const double px = radius_px > 0 ? radius_px : 0.5 * length(spacing) * frame.pixels_per_unit(zc);
  out.radius = px * frame.supersample();
  if (!(out.radius > 0) || !std::isfinite(out.radius)) return false;
  out.depth = frame.camera().depth(centre);
  out.box = SampleRect{floor_to_int(out.cx - out.radius - 0.5), floor_to_int(out.cy - out.radius - 0.5),
                       ceil_to_int(out.cx + out.radius - 0.5), ceil_to_int(out.cy + out.radius - 0.5)}
                .intersect(frame.bounds());
  return !out.box.empty();
}

}  // namespace vob
