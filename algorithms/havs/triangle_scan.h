// HAVS's own scan of a triangle whose vertices are all in front of the eye (exact sampling
// rule): the same samples and the same t as PolygonRaster::setup + scan, at less cost.
//
// The edge functions and the depth plane are PolygonRaster's own (triangle_edges,
// depth_plane), so the rule is shared, not copied. What differs is how a row is walked.
// PolygonRaster bounds a row by a conservative span and then evaluates the three exact edge
// functions c + m . X at every sample. Here each edge also gives, per row, the samples where
// its affine form a x + b y + k exceeds +eta (eta bounds |exact - affine|, the bound span()
// already relies on): there the exact value is > 0 and the sample is inside that edge without
// evaluating it. Only the samples within eta of an edge, in practice none but those an edge
// passes through exactly, take the exact test, so the decisions are PolygonRaster's. Each
// threshold is widened by a slack far above the rounding of its own evaluation.
// Depths: t = num / (n . X) * |X| with |X| from a per-sample table of the same length(X).
#pragma once
#include <cmath>
#include <cstdint>

#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"

namespace vob::havs {

class TriangleScan {
 public:
  // v: the triangle, every vertex in front of the eye. False when it covers no ray.
  bool setup(const SampleFrame& frame, const Vec3* v) {
    frame_ = &frame;
    if (!PolygonRaster::depth_plane(frame, v, 3, plane_)) return false;
    if (!PolygonRaster::triangle_edges(frame, v[0], v[1], v[2], e_)) return false;
    const double ymax = frame.rows() + 1.0;
    for (int i = 0; i < 3; ++i) {
      const PolygonRaster::Edge& e = e_[i];
      inv_a_[i] = e.a != 0 ? 1.0 / e.a : 0.0;
      slack_[i] = 1e-12 * (std::fabs(e.b) * ymax + std::fabs(e.k) + e.eta) * std::fabs(inv_a_[i]) + 1e-9;
    }
    return true;
  }

  // emit(sx, sy, t, X) for every covered sample of `clip` (within the frame), row by row
  // bottom up, left to right, as PolygonRaster::scan. len: |X| per sample (perspective).
  template <class Emit>
  void scan(const SampleRect& clip, const double* len, Emit&& emit) const {
    const SampleFrame& fr = *frame_;
    const bool ortho = fr.ortho();
    const int cols = fr.cols();
    for (int sy = clip.y0; sy <= clip.y1; ++sy) {
      int p0 = clip.x0, p1 = clip.x1, c0 = clip.x0, c1 = clip.x1;
      if (!row_range(sy, p0, p1, c0, c1)) continue;
      const Vec3 row = fr.row_term(sy);
      const double* lrow = ortho ? nullptr : len + int64_t(sy) * cols;
      const auto sample = [&](int sx, const Vec3& x) {
        const double t = ortho ? -(dot(plane_.plane.n, x) + plane_.plane.d) * plane_.inv_nf
                               : plane_.num / dot(plane_.plane.n, x) * lrow[sx];
        if ((ortho ? t >= 0 : t > 0) && std::isfinite(t)) emit(sx, sy, t, x);
      };
      for (int sx = p0; sx <= p1; ++sx) {
        const Vec3 x = row + fr.col_term(sx);
        if ((sx < c0 || sx > c1) && !inside_exact(x)) continue;
        sample(sx, x);
      }
    }
  }

 private:
  // Possible samples [p0, p1] and certainly inside ones [c0, c1] of row sy (clipped to the
  // incoming ranges); false when none is possible.
  bool row_range(int sy, int& p0, int& p1, int& c0, int& c1) const {
    const double y = sy + 0.5;
    for (int i = 0; i < 3; ++i) {
      const PolygonRaster::Edge& e = e_[i];
      const double base = e.b * y + e.k;
      if (e.a == 0) {
        if (!(base >= -e.eta)) return false;
        if (!(base > e.eta)) c0 = 1, c1 = 0;  // within eta: exact tests
        continue;
      }
      const double lo = (-e.eta - base) * inv_a_[i], hi = (e.eta - base) * inv_a_[i];
      if (!(std::isfinite(lo) && std::isfinite(hi))) {
        c0 = 1, c1 = 0;
        continue;
      }
      const double s = slack_[i];
      if (e.a > 0) {
        p0 = std::max(p0, ceil_to_int(lo - s - 0.5));
        c0 = std::max(c0, floor_to_int(hi + s - 0.5) + 1);
      } else {
        p1 = std::min(p1, floor_to_int(lo + s - 0.5));
        c1 = std::min(c1, ceil_to_int(hi - s - 0.5) - 1);
      }
    }
    return p0 <= p1;
  }
  // PolygonRaster's own decision at the sample.
  bool inside_exact(const Vec3& x) const {
    for (const PolygonRaster::Edge& e : e_) {
      const double v = e.c + dot(e.m, x);
      if (v < 0 || (v == 0 && !e.own)) return false;
    }
    return true;
  }

  const SampleFrame* frame_ = nullptr;
  PolygonRaster::DepthPlane plane_;
  PolygonRaster::Edge e_[3];
  double inv_a_[3] = {}, slack_[3] = {};
};

}  // namespace vob::havs
