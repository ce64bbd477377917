#include "harness/raster/cell_clip.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "harness/geometry/predicates.h"
#include "harness/scene/cell_types.h"
#include "harness/scene/input_error.h"

namespace vob {

ProjectedPoints project_points(const SampleFrame& frame, const std::vector<Vec3>& points) {
  ProjectedPoints p;
  const size_t n = points.size();
  p.x.resize(n);
  p.y.resize(n);
  p.zc.resize(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!frame.project(points[i], p.x[i], p.y[i], p.zc[i])) p.x[i] = p.y[i] = 0;
    }
  });
  if (!frame.ortho())
    for (size_t i = 0; i < n; ++i)
      if (!(p.zc[i] > 0)) p.all_in_front = false;
  return p;
}

double oracle_min_segment(const Aabb& bounds, const Camera& view) {
  const double r = bounds.radius();
  const double t_far = length(view.eye - bounds.center()) + r;
  if (t_far > kMaxEyeRadii * r)
    throw InputError("camera", "eye", "is " + short_number(t_far / r) +
                                           " scene radii from the scene, beyond " +
                                           short_number(kMaxEyeRadii) +
                                           ": depths from it are known to 1e-15 of themselves, "
                                           "coarser than 1e-4 of the scene");
  return std::max(kMinSegmentRelative * r, kMinSegmentFarRelative * t_far);
}

CellClipper::CellClipper(const SampleFrame& frame, const CellMesh& mesh,
                         const ProjectedPoints& projected, double min_length)
    : frame_(frame), mesh_(mesh), proj_(projected), min_length_(min_length) {}

SampleRect CellClipper::bounds(int32_t c) const {
  const int32_t* p = mesh_.cell_points(c);
  const int n = mesh_.cell_size(c);
  bool any_front = false, all_front = true;
  for (int i = 0; i < n; ++i) {
    const bool front = frame_.ortho() ? proj_.zc[p[i]] >= 0 : proj_.zc[p[i]] > 0;
    any_front |= front;
    all_front &= front;
  }
  if (!any_front) return {};  // wholly behind the eye (plane)
  if (all_front || frame_.ortho()) {
    // The image of a convex cell in front of the eye is the hull of its projected vertices.
    double lx = proj_.x[p[0]], hx = lx, ly = proj_.y[p[0]], hy = ly;
    for (int i = 1; i < n; ++i) {
      lx = std::min(lx, proj_.x[p[i]]), hx = std::max(hx, proj_.x[p[i]]);
      ly = std::min(ly, proj_.y[p[i]]), hy = std::max(hy, proj_.y[p[i]]);
    }
    return SampleRect{floor_to_int(lx - 0.5), floor_to_int(ly - 0.5), ceil_to_int(hx - 0.5),
                      ceil_to_int(hy - 0.5)}
        .intersect(frame_.bounds());
  }
  // Crossing the eye plane: every ray meeting the cell at t > 0 leaves it through a face at
  // t > 0, so the union of the faces' exact (half-plane) bounds covers it.
  SampleRect r;
  const LocalFaces& lf = cell_local_faces(mesh_.types[c]);
  for (int f = 0; f < lf.count; ++f) {
    Vec3 v[4];
    for (int i = 0; i < lf.size[f]; ++i) v[i] = mesh_.points[p[lf.v[f][i]]];
    PolygonRaster pr;
    if (pr.setup(frame_, v, lf.size[f])) r = r.unite(pr.bounds());
  }
  return r;
}

namespace {
// Far above the rounding of n.v (relative to |n| |v|) and of the Newell normal's direction,
// far below any real angle: beyond it the double sign is the exact one.
constexpr double kSideFilter = 1e-12;
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
double max_abs(Vec3 v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }
double sum_abs(Vec3 v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }
}  // namespace

int CellClipper::edge_side(int k, const Vec3& x) const {
  if (frame_.ortho()) {
    const double v = dot(n_[k], x - o_[k]);
    if (std::fabs(v) > kSideFilter * nlen_[k] * (length(x - o_[k]) + length(o_[k])))
      return sign_of(v);
    return orient3d(qa_[k], qb_[k], qc_[k], x);
  }
  const double v = dot(n_[k], x);
  if (std::fabs(v) > kSideFilter * nlen_[k] * length(x)) return sign_of(v);
  return orient_direction(qa_[k], qb_[k], qc_[k], x);
}

void CellClipper::setup(int32_t c) {
  CellPlanes planes;
  cell_face_planes(mesh_, c, planes);
  nf_ = planes.count;
  const int32_t* p = mesh_.cell_points(c);
  const LocalFaces& lf = cell_local_faces(mesh_.types[c]);
  const Vec3 eye = frame_.eye(), fwd = frame_.forward();
  any_edge_ = false;
  for (int f = 0; f < nf_; ++f) {
    const Vec3 nrm = planes.n[f];
    n_[f] = nrm;
    o_[f] = planes.o[f];
    k_[f] = frame_.ortho() ? dot(nrm, fwd) : -dot(nrm, eye - planes.o[f]);
    // A ray lying in the plane runs along the boundary of the cells on both sides; it
    // counts as inside the one whose outward normal's first non-zero component is
    // negative. Coplanar faces of other cells decide the same way, so along such a ray all
    // segments come from cells on one side of the plane.
    const double lead = nrm.x != 0 ? nrm.x : (nrm.y != 0 ? nrm.y : nrm.z);
    own_[f] = lead < 0;
    // Edge-on (cell_clip.h): only when k is within rounding of 0, then decided exactly on
    // the face's points (a warped quad is never edge-on: no plane holds its points).
    // (Max-norm bounds, no square roots: |n.v| <= |n|_1 |v|_inf; this runs for every face.)
    edge_[f] = false;
    const double scale = frame_.ortho() ? max_abs(fwd)
                                        : max_abs(eye - planes.o[f]) + max_abs(eye) + max_abs(planes.o[f]);
    if (std::fabs(k_[f]) > kSideFilter * sum_abs(nrm) * scale) continue;
    const Vec3 q0 = mesh_.points[p[lf.v[f][0]]], q1 = mesh_.points[p[lf.v[f][1]]],
               q2 = mesh_.points[p[lf.v[f][2]]];
    const bool quad = lf.size[f] == 4;
    const Vec3 q3 = quad ? mesh_.points[p[lf.v[f][3]]] : q0;
    if (frame_.ortho()) {
      if (orient_direction(q0, q1, q2, fwd) != 0 || (quad && orient_direction(q0, q2, q3, fwd) != 0))
        continue;
    } else if (orient3d(q0, q1, q2, eye) != 0 || (quad && orient3d(q0, q2, q3, eye) != 0)) {
      continue;
    }
    edge_[f] = any_edge_ = true;
    k_[f] = 0;
    nlen_[f] = length(nrm);
    qa_[f] = q0, qb_[f] = q1, qc_[f] = q2;
    // The exact normal's first non-zero component, from the points (the Newell normal's
    // components of a slanted plane like x = y carry rounding where they should be 0).
    const int sx = orient2d(q0.y, q0.z, q1.y, q1.z, q2.y, q2.z);
    const int sy = orient2d(q0.z, q0.x, q1.z, q1.x, q2.z, q2.x);
    const int sz = orient2d(q0.x, q0.y, q1.x, q1.y, q2.x, q2.y);
    own_[f] = (sx != 0 ? sx : (sy != 0 ? sy : sz)) < 0;
  }
}

}  // namespace vob
