// Limits on where a scene may lie, checked at load so that a bad file is refused with its
// name instead of failing later in the camera or the oracle: views square distances, so
// |x| beyond 1e150 overflows, and an extent that is tiny in absolute terms (underflow) or
// relative to the coordinates (below double resolution) leaves no view to take.
#pragma once
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"

namespace vob {

inline constexpr double kMaxAbsCoordinate = 1e150;
inline constexpr double kMinExtent = 1e-100;          // largest bounding-box side, absolute
inline constexpr double kMinRelativeExtent = 1e-12;   // ... relative to the largest |coordinate|

// Every point finite and within kMaxAbsCoordinate (InputError naming the first bad point),
// then check_extent on their bounding box.
void check_coordinates(const std::vector<Vec3>& points, const std::string& source);
// InputError naming `source` when the box is empty or degenerate as described above.
void check_extent(const Aabb& box, const std::string& source);

}  // namespace vob
