#include "harness/scene/triangle_soup.h"

#include "harness/scene/coordinates.h"
#include "harness/scene/input_error.h"

namespace vob {

void validate_triangle_soup(const TriangleSoup& s, const std::string& source) {
  if (s.tris.empty()) throw InputError(source, "triangles", "the surface has no triangles");
  check_coordinates(s.points, source);
  const auto np = static_cast<int64_t>(s.points.size());
  for (size_t t = 0; t < s.tris.size(); ++t) {
    const auto& tr = s.tris[t];
    for (int32_t v : tr)
      if (v < 0 || v >= np)
        throw InputError(source, "triangle " + std::to_string(t),
                         "point index " + std::to_string(v) + " out of range");
    const Vec3 n = cross(s.points[tr[1]] - s.points[tr[0]], s.points[tr[2]] - s.points[tr[0]]);
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2] || dot(n, n) == 0.0)
      throw InputError(source, "triangle " + std::to_string(t), "has zero area (degenerate)");
  }
}

}  // namespace vob
