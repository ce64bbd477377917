// Cell fragments: the segment [t_in, t_out] of each sample's ray inside a convex cell,
// by Cyrus-Beck clipping of the ray against the cell's outward face planes.
//
// The planes are the oracle's cell model (harness/scene/cell_planes.h): Newell planes from
// each face's canonical point order, so the two cells sharing a face use exactly negated
// planes and the segments of face neighbours meet without gap or overlap; a non-planar quad
// is replaced by its Newell normal through its canonical first point, and the cell is the
// intersection of its face half-spaces. A ray lying exactly in a face plane (an
// orthographic view along a grid axis, sampling on grid lines) belongs to the cells on one
// side of that plane only, decided by the sign of the plane's normal, the same way for all
// coplanar faces: without such a rule, rounding would pick cells on both sides at random.
//
// Only what is in front of the eye counts: segments are clipped to t >= 0, so an eye inside
// a cell gives [0, t_out]; orthographic rays start on the eye plane, so geometry behind the
// eye plane is dropped (the same rule the polygon rasterizer applies). Segments not longer
// than min_length are dropped: they are rays grazing an edge or vertex, whose length is
// rounding noise. The oracle uses min_length = oracle_min_segment(scene bounds, view):
// kMinSegmentRelative * scene bounding radius, more when the eye is far (the constants are
// defined with the cell model, cell_planes.h).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"
#include "harness/scene/cell_mesh.h"
#include "harness/scene/cell_planes.h"

namespace vob {

// Every point of a mesh projected once per view: sample coordinates and view depth.
struct ProjectedPoints {
  std::vector<double> x, y, zc;
  bool all_in_front = true;  // perspective: every zc > 0
};
ProjectedPoints project_points(const SampleFrame& frame, const std::vector<Vec3>& points);

// The oracle's min_length for a scene with bounding box `bounds` seen by `view`:
// kMinSegmentRelative of the radius, or kMinSegmentFarRelative of the largest t a segment
// can have (eye to the far side of the bounding sphere) when the eye is so far away that
// t's rounding would come near the first (cell_planes.h). InputError ("camera", "eye")
// when the eye is more than kMaxEyeRadii from the scene.
double oracle_min_segment(const Aabb& bounds, const Camera& view);

class CellClipper {
 public:
  CellClipper(const SampleFrame& frame, const CellMesh& mesh, const ProjectedPoints& projected,
              double min_length);
  // Conservative sample rectangle of cell c (empty when it lies behind the eye).
  SampleRect bounds(int32_t c) const;
  // Prepares cell c for scan(): its outward face planes.
  void setup(int32_t c);
  // Calls emit(sx, sy, t_in, t_out) for every sample of `clip` whose ray meets the prepared
  // cell in a segment longer than min_length.
  template <class Emit>
  void scan(const SampleRect& clip, Emit&& emit) const;

 private:
  const SampleFrame& frame_;
  const CellMesh& mesh_;
  const ProjectedPoints& proj_;
  double min_length_;
  int nf_ = 0;
  Vec3 n_[6];     // outward normals
  Vec3 o_[6];     // a point of each face plane (its canonical first vertex)
  double k_[6];   // perspective: -n.(eye - o); orthographic: n.forward
  bool own_[6];   // a ray lying in the face plane counts as inside (see setup)
  // Edge-on faces: the eye lies exactly in the plane of the face's points (orthographic:
  // the view direction is parallel to it). Rays can lie in such a plane, and whether they
  // do must not depend on rounding: n.(eye - o) and n.D of a plane like x = y are rounding
  // noise, not zero, so cells on either side would get the ray at random (a slanted
  // plane's cells on one side here, on the other side there). For these faces k is 0 and
  // the side of each ray comes from exact predicates on the face's points qa, qb, qc (an
  // outward loop), own_ from the exact normal's sign.
  bool edge_[6];
  bool any_edge_ = false;  // some edge_[k] (almost never: the scan's common path skips them)
  Vec3 qa_[6], qb_[6], qc_[6];
  double nlen_[6];  // |n|
  // The side of sample vector x (D or O) relative to edge-on face k: the sign of n.D
  // (perspective) or of n.(O - o) (orthographic), exact.
  int edge_side(int k, const Vec3& x) const;
};

template <class Emit>
void CellClipper::scan(const SampleRect& clip, Emit&& emit) const {
  const bool ortho = frame_.ortho();
  for (int sy = clip.y0; sy <= clip.y1; ++sy) {
    const Vec3 row = frame_.row_term(sy);
    for (int sx = clip.x0; sx <= clip.x1; ++sx) {
      const Vec3 x = row + frame_.col_term(sx);
      // Inside face k: n.(O + s D) + d < 0, i.e. s * den < num.
      double lo = 0, hi = std::numeric_limits<double>::infinity();
      for (int k = 0; k < nf_ && lo < hi; ++k) {
        double num, den;
        if (any_edge_ && edge_[k]) {  // exact side; a ray in the plane gets num == den == 0
          const int side = edge_side(k, x);
          num = ortho ? -side : 0.0;
          den = ortho ? 0.0 : side;
        } else if (ortho) {
          num = -dot(n_[k], x - o_[k]);
          den = k_[k];
        } else {
          num = k_[k];
          den = dot(n_[k], x);
        }
        if (den < 0) {
          lo = std::max(lo, num / den);
        } else if (den > 0) {
          hi = std::min(hi, num / den);
        } else if (num < 0 || (num == 0 && !own_[k]) || num != num) {
          hi = lo;  // parallel to the face and outside it (or in its plane, not owned)
        }
      }
      if (!(lo < hi) || !std::isfinite(hi)) continue;
      const double len = ortho ? 1.0 : length(x);
      const double t0 = lo * len, t1 = hi * len;
      if (t1 - t0 > min_length_) emit(sx, sy, t0, t1);
    }
  }
}

}  // namespace vob
