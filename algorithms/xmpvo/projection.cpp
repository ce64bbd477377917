#include "algorithms/xmpvo/projection.h"

#include <algorithm>
#include <cmath>

namespace vob::xmpvo {
namespace {

// Faces whose nearest vertex is within this fraction of (scene radius + eye distance) of
// a perspective eye's plane are not projected: the projection would blow up.
constexpr double kFrontRelative = 1e-9;
// Bucketing slack, relative to the projected extent: far above the rounding of projected
// doubles (~1e-15), so a face whose exact projection holds a point is always found.
constexpr double kSlackRelative = 1e-9;
// Buckets per projected face. 1 measured faster on the 200k-cell helix than 4 and 16: the
// arrangement's bucket scans grow with the buckets, the queries' scans did not shrink.
constexpr size_t kGridPerFace = 1;

}  // namespace

void Projection::run(const ExteriorFaces& ext, const Camera& view, Signs& signs, Vec3 centre,
                     double radius) {
  const size_t b = ext.face.size();
  const std::vector<Vec3>& points = ext.points;
  const Vec3 eye = view.eye, fw = view.forward(), rt = view.right(), up = view.true_up();
  const double front_min = kFrontRelative * (radius + length(eye - centre));
  facing.assign(b, 0);
  uv.resize(points.size());
  point_used.assign(points.size(), 0);
  front = back = edge_on = behind_eye = crossing_eye = 0;
  // Depth along the view direction decides which perspective faces can be projected.
  for (size_t i = 0; i < b; ++i) {
    const int n = ext.size[i];
    const int32_t* pt = &ext.vertex[4 * i];
    if (!view.ortho) {
      int in_front = 0;
      for (int k = 0; k < n; ++k) in_front += dot(points[pt[k]] - eye, fw) > front_min;
      if (in_front == 0) { ++behind_eye; continue; }
      if (in_front < n) { ++crossing_eye; continue; }
    }
    const int s = signs.eye_side(points[pt[0]], points[pt[1]], points[pt[2]]);
    if (s == 0) { ++edge_on; continue; }
    facing[i] = static_cast<int8_t>(s);
    (s > 0 ? front : back)++;
    for (int k = 0; k < n; ++k) point_used[pt[k]] = 1;
  }
  Box all{INFINITY, INFINITY, -INFINITY, -INFINITY};
  // Rounding of the projected doubles, bounded generously (d, the dot products, the
  // division); in orthographic views also the basis' departure from orthogonality.
  constexpr double kEps = 0x1p-52;
  const double skew = view.ortho ? std::fabs(dot(rt, fw)) + std::fabs(dot(up, fw)) : 0.0;
  double err_max = 0;
  for (size_t p = 0; p < points.size(); ++p) {
    if (!point_used[p]) continue;
    const Vec3 d = points[p] - eye;
    const double dn = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    double u = dot(d, rt), v = dot(d, up);
    double err = 32 * kEps * (dn + std::fabs(u) + std::fabs(v)) + 4 * skew * dn;
    if (!view.ortho) {
      const double z = dot(d, fw);
      u /= z;
      v /= z;
      err = 32 * kEps * dn * (1 + std::fabs(u) + std::fabs(v)) / z;
      if (!(z > 0)) err = INFINITY;
    }
    err_max = std::max(err_max, err);
    uv[p] = {u, v};
    all = {std::min(all.x0, u), std::min(all.y0, v), std::max(all.x1, u), std::max(all.y1, v)};
  }
  kept.clear();
  for (size_t i = 0; i < b; ++i)
    if (facing[i]) kept.push_back(static_cast<int32_t>(i));
  if (kept.empty()) all = {0, 0, 1, 1};
  const double w = std::max(all.x1 - all.x0, 0.0), h = std::max(all.y1 - all.y0, 0.0);
  slack = kSlackRelative * (std::max({std::fabs(all.x0), std::fabs(all.x1), std::fabs(all.y0),
                                      std::fabs(all.y1)}) + std::max(w, h)) + 1e-300;
  const double det_n = dot(cross(rt, up), fw);
  sign_n = (det_n > 0.5) - (det_n < -0.5);  // an orthonormal basis: +1 or -1
  uv_filter = sign_n != 0 && err_max <= slack / 8;
  grid.fit(all, slack, kGridPerFace * kept.size());
  face_box.resize(b);
  for (int32_t i : kept) {
    Box bx{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < ext.size[i]; ++k) {
      const auto [u, v] = uv[ext.vertex[4 * i + k]];
      bx = {std::min(bx.x0, u), std::min(bx.y0, v), std::max(bx.x1, u), std::max(bx.y1, v)};
    }
    face_box[i] = {bx.x0 - slack, bx.y0 - slack, bx.x1 + slack, bx.y1 + slack};
  }
  grid.fill(kept, [&](int32_t i) { return face_box[i]; }, bucket_off, bucket_faces);
}

size_t Projection::bytes() const {
  return facing.capacity() + kept.capacity() * 4 + point_used.capacity() + uv.capacity() * 16 +
         face_box.capacity() * sizeof(Box) + (bucket_off.capacity() + bucket_faces.capacity()) * 4 + grid.bytes();
}

}  // namespace vob::xmpvo
