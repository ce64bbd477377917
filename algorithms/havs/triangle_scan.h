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
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "harness/cpu_features.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"

namespace vob::havs {

class TriangleScan {
 public:
  // v: the triangle, every vertex in front of the eye. False when it covers no ray.
  // portable: the scalar loop for the rows' forms even where the CPU has AVX2 (the same
  // bits; tests compare).
  bool setup(const SampleFrame& frame, const Vec3* v, bool portable = false) {
    frame_ = &frame;
    if (!PolygonRaster::depth_plane(frame, v, 3, plane_)) return false;
    if (!PolygonRaster::triangle_edges(frame, v[0], v[1], v[2], e_)) return false;
    const double ymax = frame.rows() + 1.0;
    if (cpu_has_avx2() && !portable) {
      rows_avx2(ymax);
      return true;
    }
    special_ = false;
    Rows& r = row_;
    for (int i = 0; i < 3; ++i) {
      const PolygonRaster::Edge& e = e_[i];
      r.flat[i] = e.a == 0;
      special_ |= r.flat[i];
      if (r.flat[i]) continue;
      // lo(y) = (-eta - b y - k) / a and hi(y) = (eta - b y - k) / a as linear forms in y;
      // the slack bounds their rounding (relative to the terms' magnitudes) many times over.
      const double inv_a = 1.0 / e.a;
      r.slope[i] = e.b * inv_a;
      r.lo0[i] = (-e.eta - e.k) * inv_a;
      r.hi0[i] = (e.eta - e.k) * inv_a;
      r.finite[i] = std::isfinite(r.slope[i]) && std::isfinite(r.lo0[i]) && std::isfinite(r.hi0[i]);
      const double slack = 1e-12 * (std::fabs(e.b) * ymax + std::fabs(e.k) + e.eta) * std::fabs(inv_a) + 1e-9;
      r.slack[i] = e.a > 0 ? slack : -slack;
      r.sign[i] = e.a > 0 ? 1.0 : -1.0;
      r.off_pos[i] = e.a > 0 ? 0.0 : std::numeric_limits<double>::infinity();
      r.off_neg[i] = e.a > 0 ? std::numeric_limits<double>::infinity() : 0.0;
      special_ |= !r.finite[i];
    }
    return true;
  }

  // The rows' linear forms, per edge i < 3 (lane 3: room for four-lane stores). The fields
  // of a flat edge (a = 0) mean nothing and are never read. Public so that a test can compare
  // setup's two loops.
  struct Rows {
    double lo0[4], hi0[4], slope[4], slack[4];  // slack signed as a
    double sign[4];                             // of a
    double off_pos[4], off_neg[4];  // 0 for the edge's own kind (a > 0: pos), inf else
    bool flat[3] = {false, false, false}, finite[3] = {true, true, true};
  };
  const Rows& rows() const { return row_; }
  bool special() const { return special_; }

  // emit(sx, sy, t, X) for every covered sample of `clip` (within the frame), row by row
  // bottom up, left to right, as PolygonRaster::scan. len: |X| per sample (perspective).
  // The ranges of up to kRows rows are made first (row_ranges: without branches on the
  // edges' kinds, which mispredicted; faces are a few rows tall).
  template <class Emit>
  void scan(const SampleRect& clip, const double* len, Emit&& emit) const {
    if (frame_->ortho())
      scan_as<true>(clip, len, emit);
    else
      scan_as<false>(clip, len, emit);
  }
  // scan() for an orthographic (kOrtho) or perspective frame: no test of the kind per sample.
  template <bool kOrtho, class Emit>
  void scan_as(const SampleRect& clip, const double* len, Emit&& emit) const {
    const SampleFrame& fr = *frame_;
    constexpr bool ortho = kOrtho;
    const int cols = fr.cols();
    for (int ya = clip.y0; ya <= clip.y1; ya += kRows) {
      const int ny = std::min(clip.y1 - ya + 1, kRows);
      int p0[kRows], p1[kRows], c0[kRows], c1[kRows];
      row_ranges(ya, ny, clip, p0, p1, c0, c1);
      for (int r = 0; r < ny; ++r) {
        if (p0[r] > p1[r]) continue;
        const int sy = ya + r;
        const Vec3 row = fr.row_term(sy);
        const double* lrow = ortho ? nullptr : len + int64_t(sy) * cols;
        const auto sample = [&](int sx, const Vec3& x) {
          const double t = ortho ? -(dot(plane_.plane.n, x) + plane_.plane.d) * plane_.inv_nf
                                 : plane_.num / dot(plane_.plane.n, x) * lrow[sx];
          if ((ortho ? t >= 0 : t > 0) && std::isfinite(t)) emit(sx, sy, t, x);
        };
        for (int sx = p0[r]; sx <= p1[r]; ++sx) {
          const Vec3 x = row + fr.col_term(sx);
          if ((sx < c0[r] || sx > c1[r]) && !inside_exact(x)) continue;
          sample(sx, x);
        }
      }
    }
  }

  // Rows ya .. ya + ny - 1 (ny <= kRows; each array holds kRows): possible samples [p0, p1]
  // and certainly inside ones [c0, c1] (within clip's columns); p0 > p1 where none is
  // possible. Public so that a test can compare the kernels: `scalar` forces the portable
  // loop where the AVX2 one would run.
  void row_ranges(int ya, int ny, const SampleRect& clip, int* p0, int* p1, int* c0, int* c1,
                  bool scalar = false) const;
  static constexpr int kRows = 16;

 private:
  // Every edge slanted and finite (nearly all faces): the same bounds as row_ranges_any,
  // row by row without branches. An edge with a < 0 bounds x from above; it is applied as
  // a lower bound of -x, so both kinds are one max with the sign folded in (negation is
  // exact). floor_near is monotonic, so the max of the edges' floors is the floor of their
  // max: per row the arguments are combined first (an edge of the other kind adds +-inf),
  // then rounded once per bound. Order-independent over edges: bounds only tighten.
  void row_ranges_slanted(int ya, int ny, const SampleRect& clip, int* p0, int* p1, int* c0, int* c1) const {
    const int lim = frame_->cols();
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int r = 0; r < ny; ++r) {
      const double y = ya + r + 0.5;
      double u_pos = inf, u_neg = inf, w_pos = -inf, w_neg = -inf;
      for (int i = 0; i < 3; ++i) {
        const Rows& e = row_;
        const double lo = e.lo0[i] - e.slope[i] * y, hi = e.hi0[i] - e.slope[i] * y;
        const double u = -e.sign[i] * (lo - e.slack[i] - 0.5), w = e.sign[i] * (hi + e.slack[i] - 0.5);
        u_pos = std::min(u_pos, u + e.off_pos[i]), u_neg = std::min(u_neg, u + e.off_neg[i]);
        w_pos = std::max(w_pos, w - e.off_pos[i]), w_neg = std::max(w_neg, w - e.off_neg[i]);
      }
      p0[r] = std::max(clip.x0, -floor_near(u_pos, lim));
      p1[r] = std::min(clip.x1, floor_near(u_neg, lim));
      c0[r] = std::max(clip.x0, floor_near(w_pos, lim) + 1);
      c1[r] = std::min(clip.x1, -(floor_near(w_neg, lim) + 1));
    }
  }
  // The same, four rows a step with the same operations lane by lane (no FMA), so the same
  // bits (triangle_scan.cpp; havs_triangle_scan_test compares them).
  void row_ranges_slanted_avx2(int ya, int ny, const SampleRect& clip, int* p0, int* p1, int* c0, int* c1) const;
  // Any edges, flat (a = 0) or with non-finite forms among them.
  void row_ranges_any(int ya, int ny, const SampleRect& clip, int* p0, int* p1, int* c0, int* c1) const {
    for (int r = 0; r < ny; ++r) p0[r] = c0[r] = clip.x0, p1[r] = c1[r] = clip.x1;
    const int lim = frame_->cols();
    for (int i = 0; i < 3; ++i) {
      const PolygonRaster::Edge& e = e_[i];
      const Rows& w = row_;
      if (w.flat[i]) {
        for (int r = 0; r < ny; ++r) {
          const double base = e.b * (ya + r + 0.5) + e.k;
          if (!(base >= -e.eta)) p0[r] = 1, p1[r] = 0;       // no sample on this row
          else if (!(base > e.eta)) c0[r] = 1, c1[r] = 0;    // within eta: exact tests
        }
      } else if (!w.finite[i]) {
        for (int r = 0; r < ny; ++r) c0[r] = 1, c1[r] = 0;
      } else if (w.slack[i] > 0) {  // a > 0: x >= lo possible, x > hi certain
        for (int r = 0; r < ny; ++r) {
          const double y = ya + r + 0.5, lo = w.lo0[i] - w.slope[i] * y, hi = w.hi0[i] - w.slope[i] * y;
          p0[r] = std::max(p0[r], -floor_near(-(lo - w.slack[i] - 0.5), lim));
          c0[r] = std::max(c0[r], floor_near(hi + w.slack[i] - 0.5, lim) + 1);
        }
      } else {  // a < 0: x <= lo possible, x < hi certain
        for (int r = 0; r < ny; ++r) {
          const double y = ya + r + 0.5, lo = w.lo0[i] - w.slope[i] * y, hi = w.hi0[i] - w.slope[i] * y;
          p1[r] = std::min(p1[r], floor_near(lo - w.slack[i] - 0.5, lim));
          c1[r] = std::min(c1[r], -floor_near(-(hi + w.slack[i] - 0.5), lim) - 1);
        }
      }
    }
  }
  // floor(v) where it matters, for v compared with sample indices in [0, lim): clamped to
  // [-lim - 4, lim + 2] and truncated after a shift that makes it positive (no libm floor; the
  // shift's rounding, ~1e-12 samples, is far below the slack).
  static int floor_near(double v, int lim) {
    const double c = std::min(std::max(v, -double(lim) - 4.0), double(lim) + 2.0);
    const double off = double(lim) + 8.0;
    return int(c + off) - int(off);
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
  // setup's loop with the three edges in AVX2 lanes: the same operations lane by lane (no
  // FMA), so the same bits in row_ for every edge that is not flat (triangle_scan.cpp).
  void rows_avx2(double ymax);
  Rows row_;
  bool special_ = false;  // some edge flat or not finite: row_ranges_any
};

}  // namespace vob::havs
