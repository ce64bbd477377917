// The faces of one HAVS frame binned into bands of rows, in drawing order, and the scan of a
// band that turns them into k-buffer fragments (used by the timed k-buffer pass and by the
// untimed analysis, so both see the same fragments).
//
// Binning costs a projection per mesh point (not per face vertex) and a rectangle per face:
// the rectangle is the range of sample centres the projected face can reach, the same range
// PolygonRaster's own rejection test uses, so a face lands only in bands it may cover and
// the harness rasterizer's setup runs once per (face, band), reusing the projected points.
// Items carry the face's point ids, so a band reads its list sequentially (the profile
// showed the scattered face records and point ids as the scan's hottest stalls).
// The scalar at a fragment is the face's linear function along the sample's ray, evaluated
// from the ray parameter t without forming the 3D point: s = A + (t / |D|) (g . D) in
// perspective, 1/|D| tabled per sample (the same value as before up to double rounding).
#pragma once
#include <cstdint>
#include <type_traits>
#include <vector>

#include "algorithms/havs/havs_frame.h"
#include "algorithms/havs/triangle_scan.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"

namespace vob::havs {

constexpr int32_t kFrontTriangle = -1, kTriangle = -2;

struct BandItem {
  int32_t tag;      // face * 2 + (1 on the mesh boundary), as KEntry::tag
  int32_t ids[4];   // the face's points; for a triangle ids[3] is kFrontTriangle when all
                    // three points are in front of the eye (then the scan reads no
                    // projected point), kTriangle otherwise
  SampleRect rect;  // the sample centres the face may cover
};

struct FaceBins {
  int rows_per_band = 16, bands = 0;
  std::vector<int64_t> start;                // size bands + 1
  std::vector<BandItem> items;               // per band, in drawing order
  std::vector<ProjectedVertex> projected;    // per mesh point
  std::vector<double> inv_len, len;          // per sample: 1 / |D| and |D| (perspective only)
  std::vector<BandItem> made;                // binning scratch: per face in drawing order
  std::vector<int64_t> slot;                 // binning scratch: per (chunk, band)
  size_t bytes() const {
    return items.capacity() * sizeof(BandItem) + projected.capacity() * sizeof(ProjectedVertex) +
           (inv_len.capacity() + len.capacity()) * 8 + made.capacity() * sizeof(BandItem) + (start.capacity() + slot.capacity()) * 8;
  }
};

// Rows per band: 16 rows of 512 pixels with k = 8 entries is 1 MB of k-buffer, cache sized.
// At k = 2, 32 rows are 768 KB of pixel records, still within L2, and a face crossing a band
// edge is set up once per band: at 16 rows that was a fifth of the items on the 200k helix
// (528k items for 422k faces).
constexpr int kBandRows = 16, kBandRowsK2 = 32;

// Bins the faces of `order` (drawing order) for `frame` into `b` (its buffers reused);
// parallel under the TBB limit, the result independent of the thread count.
void bin_faces(const FaceData& fd, const SampleFrame& frame, const std::vector<int32_t>& order, FaceBins& b,
               int rows_per_band = kBandRows);

// Calls visit(local pixel index, entry) for every fragment of band q, in drawing order.
// Triangles with every point in front of the eye take TriangleScan (the same fragments as
// PolygonRaster, cheaper); `generic` forces PolygonRaster for all (the test's reference).
template <class Visit>
void scan_band(const FaceData& fd, const SampleFrame& frame, const FaceBins& b, int q, Visit&& visit,
               bool generic = false) {
  const int row0 = q * b.rows_per_band, row1 = std::min(frame.rows(), row0 + b.rows_per_band);
  const SampleRect band{0, row0, frame.cols() - 1, row1 - 1};
  const bool ortho = frame.ortho();
  const bool gl = frame.rule() == RasterRule::gl;  // llvmpipe's coverage (render_kbuffer)
  const Vec3 eye = frame.eye(), fwd = frame.forward();
  const int cols = frame.cols();
  const Vec3* points = fd.scene.mesh().points.data();
  const double* inv_len = b.inv_len.data();
  const double* len = b.len.data();
  PolygonRaster pr;
  TriangleScan ts;
  Vec3 v[4];
  ProjectedVertex pv[4];
  const int64_t end = b.start[q + 1];
  for (int64_t it = b.start[q]; it < end; ++it) {
    if (it + 8 < end) {  // faces arrive in depth order: their records are scattered
      const BandItem& ahead = b.items[it + 8];
      if (ahead.ids[3] >= 0) __builtin_prefetch(&fd.quad_slot[ahead.tag >> 1]);
      __builtin_prefetch(&fd.scalar[ahead.tag >> 1]);
      const bool ahead_fast = ahead.ids[3] == kFrontTriangle && !generic && frame.rule() == RasterRule::exact;
      for (int i = 0; i < 4 && ahead.ids[i] >= 0; ++i) {
        __builtin_prefetch(&points[ahead.ids[i]]);
        if (!ahead_fast) __builtin_prefetch(&b.projected[ahead.ids[i]]);
      }
    }
    const BandItem& item = b.items[it];
    const int n = item.ids[3] < 0 ? 3 : 4;
    for (int i = 0; i < n; ++i) v[i] = points[item.ids[i]];
    const int32_t tag = item.tag, f = tag >> 1;
    if (item.ids[3] == kFrontTriangle && !generic && frame.rule() == RasterRule::exact) {
      if (!ts.setup(frame, v)) continue;
      const FaceData::Linear& l1 = fd.scalar[f];
      const double a1 = ortho ? l1.c : l1.c + dot(l1.g, eye), b1 = ortho ? dot(l1.g, fwd) : 0;
      // One instance of the sample loop per kind of frame (no test of the kind per sample).
      const auto front_scan = [&](auto kind) __attribute__((always_inline)) {
        constexpr bool kOrtho = decltype(kind)::value;
        ts.template scan_as<kOrtho>(item.rect.intersect(band), len, [&](int sx, int sy, double t, const Vec3& x) {
          const double lam = kOrtho ? 1.0 : t * inv_len[int64_t(sy) * cols + sx];
          const double s = a1 + b1 * t + lam * dot(l1.g, x);
          visit((sy - row0) * cols + sx, KEntry{float(t), clamp01(s), tag});
        });
      };
      if (ortho)
        front_scan(std::true_type{});
      else
        front_scan(std::false_type{});
      continue;
    }
    for (int i = 0; i < n; ++i) pv[i] = b.projected[item.ids[i]];
    if (!pr.setup(frame, v, n, pv)) continue;
    // s(t) along the ray X: perspective p = eye + X t/|X|, orthographic p = X + fwd t.
    const auto along = [&](const FaceData::Linear& l, double& a, double& b_t) {
      a = ortho ? l.c : l.c + dot(l.g, eye);
      b_t = ortho ? dot(l.g, fwd) : 0;
    };
    const int32_t qs = fd.quad_slot[f];
    const FaceData::Linear& l1 = fd.scalar[f];
    double a1, b1;
    along(l1, a1, b1);
    if (qs < 0) {
      pr.scan(item.rect.intersect(band), [&](int sx, int sy, double t) {
        if (gl) t = pr.plane_depth(sx, sy);  // the face plane's depth, as the GL shader's
        const Vec3 x = frame.x(sx, sy);
        const double lam = ortho ? 1.0 : t * inv_len[int64_t(sy) * cols + sx];
        const double s = a1 + b1 * t + lam * dot(l1.g, x);
        visit((sy - row0) * cols + sx, KEntry{float(t), clamp01(s), tag});
      });
    } else {
      const FaceData::Linear &l2 = fd.quad_half2[qs], &ls = fd.quad_split[qs];
      double a2, b2, as, bs;
      along(l2, a2, b2);
      along(ls, as, bs);
      pr.scan(item.rect.intersect(band), [&](int sx, int sy, double t) {
        if (gl) t = pr.plane_depth(sx, sy);  // the face plane's depth, as the GL shader's
        const Vec3 x = frame.x(sx, sy);
        const double lam = ortho ? 1.0 : t * inv_len[int64_t(sy) * cols + sx];
        const bool second = as + bs * t + lam * dot(ls.g, x) > 0;
        const double s = second ? a2 + b2 * t + lam * dot(l2.g, x) : a1 + b1 * t + lam * dot(l1.g, x);
        visit((sy - row0) * cols + sx, KEntry{float(t), clamp01(s), tag});
      });
    }
  }
}

}  // namespace vob::havs
