// The plane of a planar (or nearly planar) polygon of 3 or 4 points: Newell's normal, whose
// length is twice the area, and the centroid of the points. Computed relative to the first
// point, so that the differences of nearby coordinates are exact and the normal keeps full
// precision far from the origin (the `offset` hard case puts meshes at 1e7).
#pragma once
#include "harness/geometry/vec3.h"

namespace vob {

struct PolygonPlane {
  Vec3 normal;    // right-hand normal of the loop, not normalised
  Vec3 centroid;  // mean of the points
};

inline PolygonPlane newell_plane(const Vec3* v, int n) {
  const Vec3 o = v[0];
  Vec3 nrm, sum;
  for (int i = 0; i < n; ++i) {
    const Vec3 a = v[i] - o, b = v[(i + 1) % n] - o;
    nrm += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    sum += a;
  }
  return {nrm, o + sum / n};
}

}  // namespace vob
