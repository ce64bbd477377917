// XMPVO's "project" phase: the facing of every exterior face at a view, the projected
// doubles of their vertices (for bucketing and depth keys only; every decision is a sign
// from Signs) and the bucket grid of the projected faces.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/bucket_grid.h"
#include "algorithms/xmpvo/signs.h"
#include "harness/scene/exterior_faces.h"
#include "harness/view/camera.h"

namespace vob::xmpvo {

struct Projection {
  std::vector<int8_t> facing;  // per exterior face: +1 front, -1 back, 0 not projected
  std::vector<int32_t> kept;   // the projected faces
  std::vector<uint8_t> point_used;
  std::vector<std::pair<double, double>> uv;  // per exterior point
  std::vector<Box> face_box;
  int64_t front = 0, back = 0, edge_on = 0, behind_eye = 0, crossing_eye = 0;
  double slack = 0;  // bucketing slack in projected units
  // The double sign filter of uv_filter.h: sign of det(right, up, forward), and whether
  // every projected point's rounding bound is below slack / 8 (off: exact predicates only).
  int sign_n = 0;
  bool uv_filter = false;
  BucketGrid grid;
  std::vector<int32_t> bucket_off, bucket_faces;

  // Edge-on faces are dropped (they cover no open set); perspective faces not entirely in
  // front of the eye are skipped and counted. `centre` and `radius` bound the scene.
  void run(const ExteriorFaces& ext, const Camera& view, Signs& signs, Vec3 centre, double radius);
  Box point_box(int32_t p) const {
    const auto [u, v] = uv[p];
    return {u - slack, v - slack, u + slack, v + slack};
  }
  size_t bytes() const;
};

}  // namespace vob::xmpvo
