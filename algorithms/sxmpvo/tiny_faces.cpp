#include "algorithms/sxmpvo/tiny_faces.h"

#include <algorithm>

#include "harness/cpu_features.h"
#include "harness/raster/edge_lanes_avx2.h"
#include "harness/raster/row_step_avx2.h"
#include "harness/raster/sample_centres.h"

namespace vob::sxmpvo {

namespace {
// sample_box's body, vertex i being q(i).
template <class Q>
inline BoxKind box_of(const SampleFrame& frame, int n, SampleRect& box, Q q) {
  double lx = 0, hx = 0, ly = 0, hy = 0;
  for (int i = 0; i < n; ++i) {
    const ProjectedVertex& p = q(i);
    if (!p.in_front) return BoxKind::Large;
    const double x = p.x, y = p.y;
    if (i == 0 || x < lx) lx = x;
    if (i == 0 || x > hx) hx = x;
    if (i == 0 || y < ly) ly = y;
    if (i == 0 || y > hy) hy = y;
  }
  // The samples PolygonRaster::may_cover_a_sample would let through (the same function).
  if (!sample_centres_in(frame, lx, hx, ly, hy, box)) return BoxKind::None;
  const int64_t samples = int64_t(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  return samples <= kTinyMaxSamples ? BoxKind::Tiny : BoxKind::Large;
}
}  // namespace

// Built for AVX2 too, chosen at load time: there ceil and floor are one instruction each
// (the baseline's are a dozen); both are exact, so both builds give the same boxes.
__attribute__((target_clones("avx2", "default"))) BoxKind sample_box(const SampleFrame& frame,
                                                                     const ProjectedVertex* q, int n,
                                                                     SampleRect& box) {
  return box_of(frame, n, box, [&](int i) -> const ProjectedVertex& { return q[i]; });
}

__attribute__((target_clones("avx2", "default"))) BoxKind sample_box(const SampleFrame& frame,
                                                                     const ProjectedVertex* all,
                                                                     const int32_t* ids, int n,
                                                                     SampleRect& box) {
  return box_of(frame, n, box, [&](int i) -> const ProjectedVertex& { return all[ids[i]]; });
}

namespace {

int entries_scalar(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t item,
                   int32_t rank, ABuffer::Raw* dst) {
  const int64_t cols = fr.cols();
  int n = 0;
  scan_tiny_triangle(fr, v, phase1_sign, box, [&](int sx, int sy, double t) {
    dst[n++] = ABuffer::Raw(t, item, static_cast<int32_t>(sy * cols + sx), rank);
  });
  return n;
}

// A step's four entries, the lanes of mask `m` first (pixels from `pixel`, the step's first).
__attribute__((target("avx2"), always_inline)) inline void write_step(__m256d t, int m, int32_t pixel, int32_t item,
                                                                       int32_t rank, ABuffer::Raw* dst) {
  alignas(32) double ts[4];
  alignas(16) int32_t px[4];
  _mm256_store_pd(ts, RowStepAvx2::compact_t(t, m));
  _mm_store_si128(reinterpret_cast<__m128i*>(px), _mm_add_epi32(_mm_set1_epi32(pixel), RowStepAvx2::compact_lanes(m)));
  for (int j = 0; j < 4; ++j) dst[j] = ABuffer::Raw(ts[j], item, px[j], rank);
}

// The row kernel's steps (row_step_avx2.h) over the box, each step's four entries written
// whatever its mask (the count steps by the covered ones): no jump per sample or per hit.
// Entries are placed by the edge tests' mask alone, so the next step's places do not wait
// for this step's t (a division and a square root); a step where a covered sample's t is
// not positive and finite (almost never: every vertex is in front of the eye) is written
// again by the full mask, a jump that is predicted right.
template <bool kOrtho>
__attribute__((target("avx2,popcnt"))) int entries_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p,
                                                 const SampleRect& box, int32_t item, int32_t rank,
                                                 ABuffer::Raw* dst) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const RowStepAvx2 k(e, p);
  const int cols = fr.cols();
  int n = 0;
  for (int sy = box.y0; sy <= box.y1; ++sy) {
    const Vec3 row = fr.row_term(sy);
    const __m256d rx = _mm256_set1_pd(row.x), ry = _mm256_set1_pd(row.y), rz = _mm256_set1_pd(row.z);
    for (int sx = box.x0; sx <= box.x1; sx += 4) {
      __m256d t;
      int inside;
      const int mask = k.step<kOrtho>(rx, ry, rz, cx, cy, cz, sx, box.x1, t, inside);
      const int32_t pixel = sy * cols + sx;
      write_step(t, inside, pixel, item, rank, dst + n);
      if (__builtin_expect(mask != inside, 0)) {
        write_step(t, mask, pixel, item, rank, dst + n);
        n += __builtin_popcount(mask);
      } else {
        n += __builtin_popcount(inside);
      }
    }
  }
  return n;
}

}  // namespace

// tiny_triangle_rows with the three edges in three lanes (edge_lanes_avx2.h): the same
// operations per lane as the scalar Vec3 expressions, so the same bits; the ownership
// tests as lane masks instead of a chain of scalar compares.
__attribute__((target("avx2"))) bool tiny_triangle_rows_avx2(const SampleFrame& fr, const Vec3* v,
                                                             int phase1_sign, RowEdges& e, RowDepth& depth) {
  if (!detail::depth_plane(fr, v, depth)) return false;
  const avx2::EdgeLanes l = avx2::edge_lanes(fr, v, -phase1_sign);  // facing as tiny_triangle_rows
  _mm256_storeu_pd(e.mx, l.mx), _mm256_storeu_pd(e.my, l.my), _mm256_storeu_pd(e.mz, l.mz), _mm256_storeu_pd(e.c, l.c);
  const int m = avx2::owns_zero(fr, l);
  e.own[0] = m & 1, e.own[1] = (m >> 1) & 1, e.own[2] = (m >> 2) & 1;
  return true;
}

namespace {

int entries_avx2_any(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t item,
                     int32_t rank, ABuffer::Raw* dst) {
  RowEdges e;
  RowDepth depth;
  if (!tiny_triangle_rows_avx2(fr, v, phase1_sign, e, depth)) return 0;
  return fr.ortho() ? entries_avx2<true>(fr, e, depth, box, item, rank, dst)
                    : entries_avx2<false>(fr, e, depth, box, item, rank, dst);
}

}  // namespace

TinyEntriesFn tiny_entries() { return cpu_has_avx2() ? &entries_avx2_any : &entries_scalar; }
TinyEntriesFn tiny_entries_baseline() { return &entries_scalar; }
TinyEntriesFn tiny_entries_avx2() { return cpu_has_avx2() ? &entries_avx2_any : nullptr; }

}  // namespace vob::sxmpvo
