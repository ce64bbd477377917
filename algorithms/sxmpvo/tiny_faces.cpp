#include "algorithms/sxmpvo/tiny_faces.h"

#include <algorithm>
#include <cstddef>

#include "harness/cpu_features.h"
#include "harness/raster/edge_lanes_avx2.h"
#include "harness/raster/row_step_avx2.h"
#include "harness/raster/row_step_avx512.h"
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

int entries_scalar(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t slot, ABuffer::RawBatch::Out dst) {
  const int64_t cols = fr.cols();
  int n = 0;
  scan_tiny_triangle(fr, v, phase1_sign, box, [&](int sx, int sy, double t) {
    dst.t[n] = t, dst.key[n] = ABuffer::RawBatch::make_key(static_cast<int32_t>(sy * cols + sx), slot);
    ++n;
  });
  return n;
}

// A step's four entries, the lanes of mask `m` first (pixels from `pixel`, the step's first).
__attribute__((target("avx2"), always_inline)) inline void write_step(__m256d t, int m, int32_t pixel, int32_t slot,
                                                                       ABuffer::RawBatch::Out dst) {
  const __m128i px = _mm_add_epi32(_mm_set1_epi32(pixel), RowStepAvx2::compact_lanes(m));
  _mm256_storeu_pd(dst.t, RowStepAvx2::compact_t(t, m));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst.key),
                      _mm256_or_si256(_mm256_cvtepu32_epi64(px), _mm256_set1_epi64x(int64_t(uint32_t(slot)) << 32)));
}

// The row kernel's steps (row_step_avx2.h) over the box, each step's four entries written
// whatever its mask (the count steps by the covered ones): no jump per sample or per hit.
// Entries are placed by the edge tests' mask alone, so the next step's places do not wait
// for this step's t (a division and a square root); a step where a covered sample's t is
// not positive and finite (almost never: every vertex is in front of the eye) is written
// again by the full mask, a jump that is predicted right.
template <bool kOrtho>
__attribute__((target("avx2,popcnt"))) int entries_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p,
                                                 const SampleRect& box, int32_t slot,
                                                 ABuffer::RawBatch::Out dst) {
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
      write_step(t, inside, pixel, slot, dst + n);
      if (__builtin_expect(mask != inside, 0)) {
        write_step(t, mask, pixel, slot, dst + n);
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

int entries_avx2_any(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t slot, ABuffer::RawBatch::Out dst) {
  RowEdges e;
  RowDepth depth;
  if (!tiny_triangle_rows_avx2(fr, v, phase1_sign, e, depth)) return 0;
  return fr.ortho() ? entries_avx2<true>(fr, e, depth, box, slot, dst)
                    : entries_avx2<false>(fr, e, depth, box, slot, dst);
}

// Eight entries from the lanes of mask m (in lane order) at dst, whatever m holds: a lane
// vector of depths and one of keys.
__attribute__((target("avx512f,avx512vl,avx512dq"), always_inline)) inline void write8(__m512d t, __m256i pixel,
                                                                                      __mmask8 m, int32_t slot,
                                                                                      ABuffer::RawBatch::Out dst) {
  _mm512_storeu_pd(dst.t, _mm512_maskz_compress_pd(m, t));
  const __m256i px = _mm256_maskz_compress_epi32(m, pixel);
  _mm512_storeu_si512(dst.key, _mm512_or_si512(_mm512_cvtepu32_epi64(px),
                                               _mm512_set1_epi64(int64_t(uint32_t(slot)) << 32)));
}

// One step's entries at dst; returns their number.
template <bool kOrtho>
__attribute__((target("avx512f,avx512vl,avx512dq,popcnt"), always_inline)) inline int step_entries(
    const RowStepAvx512& k, __m512d X, __m512d Y, __m512d Z, __mmask8 valid, __m256i pixel, int32_t slot,
    ABuffer::RawBatch::Out dst) {
  __m512d t;
  __mmask8 inside;
  const __mmask8 mask = k.template step<kOrtho>(X, Y, Z, valid, t, inside);
  write8(t, pixel, inside, slot, dst);
  if (__builtin_expect(mask != inside, 0)) {
    write8(t, pixel, mask, slot, dst);
    return __builtin_popcount(mask);
  }
  return __builtin_popcount(inside);
}

// Where lane j of a step falls in a box at most eight samples wide, the box's samples taken
// eight a step in scan order: the step's first sample is 8s, row 8s / w and column 8s % w
// of the box (first_row, first_col); from there lane j is `row` rows down, at column `col`.
struct DenseLanes {
  uint8_t row[8], col[8];
};
struct DenseTables {
  DenseLanes lanes[9][8];                    // [w][first column]
  uint8_t first_row[9][8], first_col[9][8];  // [w][s], s < 8: a tiny box has at most 64 samples
};
constexpr DenseTables make_dense_tables() {
  DenseTables t{};
  for (int w = 1; w <= 8; ++w) {
    for (int m = 0; m < w; ++m)
      for (int j = 0; j < 8; ++j) {
        t.lanes[w][m].row[j] = static_cast<uint8_t>((m + j) / w);
        t.lanes[w][m].col[j] = static_cast<uint8_t>((m + j) % w);
      }
    for (int s = 0; s < 8; ++s) {
      t.first_row[w][s] = static_cast<uint8_t>(8 * s / w);
      t.first_col[w][s] = static_cast<uint8_t>(8 * s % w);
    }
  }
  return t;
}
constexpr DenseTables kDense = make_dense_tables();
static_assert(kTinyMaxSamples <= 64, "kDense covers eight steps of eight samples");

// A box at most eight samples wide, its samples packed eight a step in scan order (lanes
// spanning rows), so the steps are ceil(samples / 8) whatever the box's shape, and one
// loop serves every shape: no jump on the width.
template <bool kOrtho>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,popcnt"), always_inline)) inline int dense_box(
    const SampleFrame& fr, const RowStepAvx512& k, const SampleRect& box, int32_t slot, ABuffer::RawBatch::Out dst) {
  const int cols = fr.cols(), w = box.x1 - box.x0 + 1;
  const __mmask8 in_row = static_cast<__mmask8>((1u << w) - 1);
  const __m512d bx = _mm512_maskz_loadu_pd(in_row, fr.col_x() + box.x0);  // the box's column terms
  const __m512d by = _mm512_maskz_loadu_pd(in_row, fr.col_y() + box.x0);
  const __m512d bz = _mm512_maskz_loadu_pd(in_row, fr.col_z() + box.x0);
  const double *row_x = fr.row_x(), *row_y = fr.row_y(), *row_z = fr.row_z();  // padded: eight rows load
  const __m256i vcols = _mm256_set1_epi32(cols);
  int n = 0;
  for (int s = 0, left = w * (box.y1 - box.y0 + 1); left > 0; ++s, left -= 8) {
    const int r0 = box.y0 + kDense.first_row[w][s];
    const DenseLanes& lanes = kDense.lanes[w][kDense.first_col[w][s]];
    const __m128i rb = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(lanes.row));
    const __m128i cb = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(lanes.col));
    const __m512i ri = _mm512_cvtepu8_epi64(rb), ci = _mm512_cvtepu8_epi64(cb);
    const __m512d X = _mm512_add_pd(_mm512_permutexvar_pd(ri, _mm512_loadu_pd(row_x + r0)), _mm512_permutexvar_pd(ci, bx));
    const __m512d Y = _mm512_add_pd(_mm512_permutexvar_pd(ri, _mm512_loadu_pd(row_y + r0)), _mm512_permutexvar_pd(ci, by));
    const __m512d Z = _mm512_add_pd(_mm512_permutexvar_pd(ri, _mm512_loadu_pd(row_z + r0)), _mm512_permutexvar_pd(ci, bz));
    const __mmask8 valid = static_cast<__mmask8>(left >= 8 ? 0xFF : (1u << left) - 1);
    const __m256i offsets =
        _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvtepu8_epi32(rb), vcols), _mm256_cvtepu8_epi32(cb));
    n += step_entries<kOrtho>(k, X, Y, Z, valid, _mm256_add_epi32(_mm256_set1_epi32(r0 * cols + box.x0), offsets),
                              slot, dst + n);
  }
  return n;
}

// The box's samples in eight lanes: boxes up to eight samples wide packed eight samples a
// step (dense_box), wider ones eight columns of a row a step.
template <bool kOrtho>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,popcnt"))) int entries_avx512(
    const SampleFrame& fr, const RowStepAvx512& k, const SampleRect& box, int32_t slot, ABuffer::RawBatch::Out dst) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const int cols = fr.cols(), w = box.x1 - box.x0 + 1;
  int n = 0;
  if (w <= 8) {
    n = dense_box<kOrtho>(fr, k, box, slot, dst);
  } else {
    const __m256i offsets = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int sy = box.y0; sy <= box.y1; ++sy) {
      const Vec3 row = fr.row_term(sy);
      const __m512d rx = _mm512_set1_pd(row.x), ry = _mm512_set1_pd(row.y), rz = _mm512_set1_pd(row.z);
      for (int sx = box.x0; sx <= box.x1; sx += 8) {
        const __mmask8 valid = static_cast<__mmask8>(box.x1 - sx >= 7 ? 0xFF : (1u << (box.x1 - sx + 1)) - 1);
        n += step_entries<kOrtho>(k, _mm512_add_pd(rx, _mm512_maskz_loadu_pd(valid, cx + sx)),
                                  _mm512_add_pd(ry, _mm512_maskz_loadu_pd(valid, cy + sx)),
                                  _mm512_add_pd(rz, _mm512_maskz_loadu_pd(valid, cz + sx)), valid,
                                  _mm256_add_epi32(_mm256_set1_epi32(sy * cols + sx), offsets), slot, dst + n);
      }
    }
  }
  return n;
}

__attribute__((target("avx512f,avx512vl,avx512dq,avx2"))) int entries_avx512_any(const SampleFrame& fr, const Vec3* v,
                                                                                 int phase1_sign, const SampleRect& box,
                                                                                 int32_t slot,
                                                                                 ABuffer::RawBatch::Out dst) {
  RowDepth depth;
  if (!detail::depth_plane(fr, v, depth)) return 0;
  const avx2::EdgeLanes l = avx2::edge_lanes(fr, v, -phase1_sign);  // facing as tiny_triangle_rows
  const RowStepAvx512 k(l, avx2::owns_zero(fr, l), depth);
  return fr.ortho() ? entries_avx512<true>(fr, k, box, slot, dst)
                    : entries_avx512<false>(fr, k, box, slot, dst);
}

}  // namespace

TinyEntriesFn tiny_entries_avx512() { return cpu_has_avx512() ? &entries_avx512_any : nullptr; }

TinyEntriesFn tiny_entries() {
  return cpu_has_avx512() ? &entries_avx512_any : cpu_has_avx2() ? &entries_avx2_any : &entries_scalar;
}
TinyEntriesFn tiny_entries_baseline() { return &entries_scalar; }
TinyEntriesFn tiny_entries_avx2() { return cpu_has_avx2() ? &entries_avx2_any : nullptr; }

}  // namespace vob::sxmpvo
