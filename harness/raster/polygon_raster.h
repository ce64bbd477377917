// Sample-centre rasterization of a convex planar polygon (3 or 4 vertices), shared by the
// oracle, the compositor and image-space algorithms (SXMPVO scans exterior faces with it).
//
// Coverage is decided per sample with edge functions of the ray, not of projected vertices:
// the edge (a, b) and the ray's origin span a plane, and the sample is inside when its ray
// lies on the polygon's side of all edge planes (Olano-Greer style homogeneous
// rasterization). This needs no near-plane clipping: a polygon crossing the eye plane
// (perspective) covers exactly the samples whose rays hit it at t > 0.
//
// Watertightness: every edge function is computed from the edge's endpoints in a canonical
// (lexicographic) order and then negated as needed, so two polygons sharing an edge compute
// bit-identical values with opposite signs at every sample. A value of exactly zero is
// settled by the top-left rule (window y up): the sample is treated as if moved right by
// epsilon and down by epsilon^2. Hence a sample on an edge shared by two projected
// polygons, or on a vertex shared by a fan, belongs to exactly one of them.
//
// Quads are split into two triangles along the diagonal through their lexicographically
// smallest vertex, the same split for every polygon listing those four points, and both
// halves take their depth from the quad's Newell plane.
//
// Under the gl sampling rule (SampleFrame::rule, raster_rule.h) coverage is llvmpipe's
// instead: snapped window coordinates, integer edge functions and its fill rule, the same
// quad split; a polygon with a vertex not in front of the eye covers nothing (GL would clip
// it at the near plane, which the GL backends place beyond the scene). Depths are GL's too:
// window depth is a plane through the snapped vertices (at the vertices' own depths), so
// 1 / view depth (orthographic: view depth) is interpolated linearly over the fixed-point
// triangle, and t is that view depth times |D|. When the frame carries GL's near and far
// planes (SampleFrame::set_gl_depth_range), an emitter taking a fourth argument also gets
// the 24-bit depth llvmpipe's depth test compares there (llvmpipe_depth.h: its float
// plane, not this one), -1 without them.
//
// Depth: the ray parameter t at which the sample's ray meets the polygon's plane
// (t = s * |D|, see sample_frame.h). Orthographic samples with t < 0 (behind the eye plane)
// are not covered.
#pragma once
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "harness/raster/llvmpipe_depth.h"
#include "harness/raster/row_coverage.h"
#include "harness/raster/sample_frame.h"

namespace vob {

struct Plane {
  Vec3 n;        // not necessarily unit length
  double d = 0;  // n . p + d = 0 on the plane
};

class PolygonRaster {
 public:
  // Prepares the polygon v[0..n) (n = 3 or 4, any orientation). Returns false when it can
  // cover no sample (seen exactly edge-on, or outside the view). InputError for other n.
  // `projected` (optional) holds ProjectedVertex::of(frame, v[i]) for each vertex.
  bool setup(const SampleFrame& frame, const Vec3* v, int n,
             const ProjectedVertex* projected = nullptr);
  // A conservative rectangle of the samples it may cover.
  SampleRect bounds() const;
  // The ray parameter t at sample (sx, sy) on the polygon's own (unsnapped) plane, under
  // either rule; NaN where the ray misses it. Under the gl rule scan() gives the depth of
  // the snapped triangles instead; a renderer that computes depth itself (the HAVS GL
  // k-buffer's shader) takes llvmpipe's coverage with this depth.
  double plane_depth(int sx, int sy) const {
    return plane_ok_ ? depth(frame_->x(sx, sy)) : std::numeric_limits<double>::quiet_NaN();
  }
  // Calls emit(sx, sy, t) (or emit(sx, sy, t, depth24), see above) for every covered
  // sample in `clip`, row by row, bottom up. An emit taking (const RowHits&, int n) gets the
  // same samples in the same order a batch at a time (hits.sx/sy/t[0, n)), without a call
  // per sample.
  template <class Emit>
  void scan(const SampleRect& clip, Emit&& emit) const;

  // The columns of rows sy to sy + 3 that triangle i (of triangles()) may cover, clipped
  // to [x0, x1]: [lo[j], hi[j]] for row sy + j, lo[j] > hi[j] when none (conservative; the
  // row's samples are then tested one by one). AVX2 when the CPU has it (rows in lanes);
  // portable: the row-by-row loop (the same columns; tests compare).
  void spans4(int i, int sy, int x0, int x1, int lo[4], int hi[4], bool portable = false) const;
  int triangles() const { return count_; }

  struct Edge {
    Vec3 m;         // inside: c + m . X(sx, sy) > 0, or == 0 and `own`
    double c = 0;
    bool own = false;
    double a = 0, b = 0, k = 0, eta = 0;  // E ~= a*x + b*y + k within eta (spans only)
  };
  struct Triangle {
    Edge e[3];
    SampleRect box;
  };
  // The building blocks of setup(), public so that a caller scanning its own way (HAVS's
  // k-buffer) uses the very same edge functions and depth plane, not a copy of the rule.
  // Edge functions of triangle (p0, p1, p2) (box not set); false when seen edge-on.
  // portable: the scalar loop even where the CPU has AVX2 (the same bits; tests compare).
  static bool triangle_edges(const SampleFrame& frame, const Vec3& p0, const Vec3& p1,
                             const Vec3& p2, Edge e[3], bool portable = false);
  struct DepthPlane {
    Plane plane;
    double num = 0, inv_nf = 0;
    // Ray parameter t at the sample with varying vector x (NaN when the ray misses it).
    double depth(const Vec3& x, bool ortho) const {
      if (ortho) return -(dot(plane.n, x) + plane.d) * inv_nf;
      return num / dot(plane.n, x) * length(x);
    }
  };
  // The plane of v[0..n) for depths; false when an orthographic view sees it edge-on.
  static bool depth_plane(const SampleFrame& frame, const Vec3* v, int n, DepthPlane& out);
  // gl rule: pixel (sx, sy) is covered when c[i] - dcdx[i] * 256 sx + dcdy[i] * 256 sy > 0
  // for every edge (the fill rule's ownership is folded into c as llvmpipe does).
  struct GlTriangle {
    int64_t c[3], dcdx[3], dcdy[3];
    SampleRect box;
    int64_t x0 = 0, y0 = 0;       // vertex 0 (fixed point)
    double q0 = 0, qx = 0, qy = 0;  // q = q0 + qx (X - x0) + qy (Y - y0), q = 1/zc or zc (ortho)
    LlvmpipeDepthPlane zplane;      // llvmpipe's depth plane, when has_z
    bool has_z = false;
    bool covers(int sx, int sy) const {
      const int64_t X = int64_t(sx) * kGlSubpixels, Y = int64_t(sy) * kGlSubpixels;
      for (int i = 0; i < 3; ++i)
        if (c[i] - dcdx[i] * X + dcdy[i] * Y <= 0) return false;
      return true;
    }
  };

 private:
  // False when no sample centre can be covered; sets box_ when every vertex projects.
  bool may_cover_a_sample(const SampleFrame& frame, const Vec3* v, int n,
                          const ProjectedVertex* projected);
  bool add_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2);
  // The polygon's plane (for depths); false when an orthographic view sees it edge-on.
  bool set_plane(const SampleFrame& frame, const Vec3* v, int n);
  // gl rule (polygon_raster_gl.cpp): fixed-point triangles of the snapped vertices.
  bool setup_gl(const SampleFrame& frame, const Vec3* v, int n, const ProjectedVertex* projected);
  // z: the vertices' float window z (llvmpipe_window_z), or null without GL's depth range.
  bool add_gl_triangle(const int64_t* x, const int64_t* y, const double* q, const float* z);
  // Columns of row sy that may be covered by triangle i (conservative), clipped to [x0, x1].
  bool span(int i, int sy, int& x0, int& x1) const;
  static RowEdges row_edges(const Triangle& t) {
    RowEdges r;
    for (int i = 0; i < 3; ++i) {
      const Edge& e = t.e[i];
      r.mx[i] = e.m.x, r.my[i] = e.m.y, r.mz[i] = e.m.z, r.c[i] = e.c, r.own[i] = e.own;
    }
    return r;
  }
  // Ray parameter t at the sample (NaN when the ray misses the plane).
  double depth(const Vec3& x) const { return plane_.depth(x, frame_->ortho()); }

  const SampleFrame* frame_ = nullptr;
  DepthPlane plane_;
  Triangle tri_[2];
  GlTriangle gl_tri_[2];
  bool gl_ = false;
  bool plane_ok_ = false;  // plane_ set (exact rule: always when setup succeeds)
  int count_ = 0;
  SampleRect box_;  // the polygon's projected bounds, valid when have_box_
  bool have_box_ = false;
};

template <class Emit>
void PolygonRaster::scan(const SampleRect& clip, Emit&& emit) const {
  const bool ortho = frame_->ortho();
  constexpr bool batched = std::is_invocable_v<Emit&, const RowHits&, int>;
  if (gl_) {
    [[maybe_unused]] RowHits batch;  // batched: the gl rule's samples gathered here
    int held = 0;
    for (int i = 0; i < count_; ++i) {
      const GlTriangle& g = gl_tri_[i];
      const SampleRect r = g.box.intersect(clip);
      for (int sy = r.y0; sy <= r.y1; ++sy)
        for (int sx = r.x0; sx <= r.x1; ++sx) {
          if (!g.covers(sx, sy)) continue;
          const double q = g.q0 + g.qx * double(int64_t(sx) * kGlSubpixels - g.x0) +
                           g.qy * double(int64_t(sy) * kGlSubpixels - g.y0);
          const double t = ortho ? q : frame_->dir_length(sx, sy) / q;
          if (!((ortho ? t >= 0 : t > 0) && std::isfinite(t))) continue;
          if constexpr (batched) {
            batch.sx[held] = sx, batch.sy[held] = sy, batch.t[held] = t;
            if (++held == kRowHitCap) emit(static_cast<const RowHits&>(batch), std::exchange(held, 0));
          } else if constexpr (std::is_invocable_v<Emit&, int, int, double, int64_t>)
            emit(sx, sy, t, g.has_z ? llvmpipe_depth24(g.zplane, sx, sy) : int64_t(-1));
          else
            emit(sx, sy, t);
        }
    }
    if constexpr (batched)
      if (held > 0) emit(static_cast<const RowHits&>(batch), held);
    return;
  }
  // Perspective hits are at t > 0 by construction; the kernel's test drops rounding noise of
  // rays that graze an edge-on polygon. Orthographic: only in front of the eye plane.
  const RowCoverageFn row_fn = row_coverage();
  const RowDepth depth{plane_.plane.n, plane_.plane.d, plane_.num, plane_.inv_nf};
  const auto one = [&](int sx, int sy, double t) {
    if constexpr (batched)
      return;  // not called: `hit` is `emit` itself
    else if constexpr (std::is_invocable_v<Emit&, int, int, double, int64_t>)
      emit(sx, sy, t, int64_t(-1));
    else
      emit(sx, sy, t);
  };
  auto& hit = [&]() -> auto& {
    if constexpr (batched) return emit; else return one;
  }();
  for (int i = 0; i < count_; ++i) {
    const SampleRect r = tri_[i].box.intersect(clip);
    const RowEdges edges = row_edges(tri_[i]);
    RowScanner rows(row_fn, *frame_, edges, depth);
    for (int sy = r.y0; sy <= r.y1; sy += 4) {
      int lo[4], hi[4];
      spans4(i, sy, r.x0, r.x1, lo, hi);
      for (int j = 0; j < 4 && sy + j <= r.y1; ++j)
        if (lo[j] <= hi[j]) rows.add(sy + j, lo[j], hi[j], hit);
    }
    rows.flush(hit);
  }
}

// Convenience: rasterize v[0..n) and emit(sx, sy, t) for every covered sample in `clip`.
template <class Emit>
void rasterize_polygon(const SampleFrame& frame, const Vec3* v, int n, const SampleRect& clip,
                       Emit&& emit) {
  PolygonRaster p;
  if (p.setup(frame, v, n)) p.scan(clip, emit);
}

// Lexicographic (x, y, z) order of points: the canonical order of edge endpoints.
inline bool lex_less(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

}  // namespace vob
