#include "harness/raster/cell_clip.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

void CellClipper::setup(int32_t c) {
  CellPlanes planes;
  cell_face_planes(mesh_, c, planes);
  nf_ = planes.count;
  for (int f = 0; f < nf_; ++f) {
    const Vec3 nrm = planes.n[f];
    n_[f] = nrm;
    o_[f] = planes.o[f];
    k_[f] = frame_.ortho() ? dot(nrm, frame_.forward()) : -dot(nrm, frame_.eye() - planes.o[f]);
    // A ray lying in the plane runs along the boundary of the cells on both sides; it
    // counts as inside the one whose outward normal's first non-zero component is
    // negative. Coplanar faces of other cells decide the same way, so along such a ray all
    // segments come from cells on one side of the plane.
    const double lead = nrm.x != 0 ? nrm.x : (nrm.y != 0 ? nrm.y : nrm.z);
    own_[f] = lead < 0;
  }
}

}  // namespace vob
