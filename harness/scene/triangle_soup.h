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

  size_t num_triangles() const { return tris.size(); }
  Aabb bounds() const {
    Aabb b;
    for (const Vec3& p : points) b.add(p);
    return b;
  }
  size_t bytes() const { return points.capacity() * sizeof(Vec3) + tris.capacity() * 12; }
};

// Finite coordinates, indices in range, no zero-area triangle (exact test). InputError else.
void validate_triangle_soup(const TriangleSoup& soup, const std::string& source);

}  // namespace vob
