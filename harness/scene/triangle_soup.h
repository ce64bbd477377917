// TriangleSoup: independent triangles (surface models) for the triangle-ordering scenes.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"

namespace vob {

struct TriangleSoup {
  std::vector<Vec3> points;
  std::vector<std::array<int32_t, 3>> tris;
  // Polygons of the file that were not planar (split as fans all the same) and the worst one's
  // distance off its plane as a fraction of its size: the reader's note says so.
  size_t warped_polygons = 0;
  double worst_warp = 0;

  size_t num_triangles() const { return tris.size(); }
  Aabb bounds() const {
    Aabb b;
    for (const Vec3& p : points) b.add(p);
    return b;
  }
  size_t bytes() const { return points.capacity() * sizeof(Vec3) + tris.capacity() * 12; }
};

// Appends a polygon of n >= 3 points (ids in range) as the fan (ids[0], ids[q], ids[q+1]).
// A polygon of more than 3 points must be split so without leaving it: every fan triangle
// facing the way of its Newell normal (a fan from a reflex corner's wrong side covers ground
// outside the polygon, an L-shape for one). One with a point more than kPolygonPlanarity of
// its size (its bounding box's diagonal) off the plane through its mean is counted in
// warped_polygons: modellers' quads often are, and a fan is one of its two splits, as VTK's
// triangle filter makes it. Points not finite are left to validate_triangle_soup.
// InputError naming `element` else.
inline constexpr double kPolygonPlanarity = 1e-6;  // above float rounding (6e-8), as VTK reads
void append_polygon(TriangleSoup& soup, const int32_t* ids, size_t n, const std::string& source,
                    const std::string& element);

// Finite coordinates, indices in range, no zero-area triangle (exact test). InputError else.
void validate_triangle_soup(const TriangleSoup& soup, const std::string& source);

}  // namespace vob
