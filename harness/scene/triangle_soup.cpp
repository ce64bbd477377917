#include "harness/scene/triangle_soup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "harness/geometry/polygon_plane.h"
#include "harness/geometry/predicates.h"
#include "harness/scene/coordinates.h"
#include "harness/scene/input_error.h"

namespace vob {

void append_polygon(TriangleSoup& s, const int32_t* ids, size_t n, const std::string& source,
                    const std::string& element) {
  if (n > 3) {
    std::vector<Vec3> v(n);
    bool finite = true;
    Aabb box;
    for (size_t q = 0; q < n; ++q) {
      v[q] = s.points[ids[q]];
      finite = finite && std::isfinite(v[q].x) && std::isfinite(v[q].y) && std::isfinite(v[q].z);
      box.add(v[q]);
    }
    if (finite) {
      const PolygonPlane plane = newell_plane(v.data(), int(n));
      const double area2 = std::sqrt(dot(plane.normal, plane.normal));  // twice the area
      const Vec3 d = box.hi - box.lo;
      const double size = std::sqrt(dot(d, d));
      const auto fail = [&](const std::string& why) {
        throw InputError(source, element, "polygon of " + std::to_string(n) + " points " + why);
      };
      const auto corners = [&](size_t q) {  // fan triangle q: its corners and their points
        return "(corners 0, " + std::to_string(q) + ", " + std::to_string(q + 1) + ": points " + std::to_string(ids[0]) +
               ", " + std::to_string(ids[q]) + ", " + std::to_string(ids[q + 1]) + ")";
      };
      // Decided exactly: in doubles a quad with a point within rounding of the diagonal from
      // its first point was read either way (a concave one fanned, a convex one refused).
      std::vector<int> facing(n - 2);
      if (!fan_facings(v.data(), n, facing.data())) fail("has zero area (degenerate)");
      if (area2 > 0) {  // else too small to measure in doubles: not counted as warped
        double worst = 0;
        for (size_t q = 0; q < n; ++q) worst = std::max(worst, std::abs(dot(v[q] - plane.centroid, plane.normal)) / area2);
        if (worst > kPolygonPlanarity * size) {
          ++s.warped_polygons;
          s.worst_warp = std::max(s.worst_warp, worst / size);
        }
      }
      for (size_t q = 1; q + 1 < n; ++q) {
        if (collinear(v[0], v[q], v[q + 1]))
          fail("has its fan triangle " + corners(q) + " on a line: zero area; give it as triangles");
        if (facing[q - 1] <= 0)
          fail("is not convex: its fan triangle " + corners(q) + " faces against the polygon and lies outside it; "
               "give it as triangles");
      }
    }
  }
  for (size_t q = 1; q + 1 < n; ++q) s.tris.push_back({ids[0], ids[q], ids[q + 1]});
}

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
