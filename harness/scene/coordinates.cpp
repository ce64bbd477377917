#include "harness/scene/coordinates.h"

#include <algorithm>
#include <cmath>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
double max_abs(Vec3 p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }
}  // namespace

void check_coordinates(const std::vector<Vec3>& points, const std::string& source) {
  Aabb box;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    if (!is_finite(p)) throw InputError(source, "point " + std::to_string(i), "coordinate is not finite");
    if (max_abs(p) > kMaxAbsCoordinate)
      throw InputError(source, "point " + std::to_string(i),
                       "coordinate " + short_number(max_abs(p)) + " is beyond +-" +
                           short_number(kMaxAbsCoordinate) + " (squared distances would overflow)");
    box.add(p);
  }
  check_extent(box, source);
}

void check_extent(const Aabb& box, const std::string& source) {
  if (box.empty()) throw InputError(source, "extent", "the scene has no points");
  const Vec3 d = box.hi - box.lo;
  const double side = std::max({d.x, d.y, d.z});
  const double scale = std::max(max_abs(box.lo), max_abs(box.hi));
  if (!(side >= kMinExtent))
    throw InputError(source, "extent", "bounding box is " + short_number(side) + " wide, below " +
                                           short_number(kMinExtent) + " (degenerate)");
  if (side < kMinRelativeExtent * scale)
    throw InputError(source, "extent", "bounding box is " + short_number(side) + " wide at coordinates of " +
                                           short_number(scale) + ", below double resolution (degenerate)");
}

}  // namespace vob
