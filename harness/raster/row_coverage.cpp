#include "harness/raster/row_coverage.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

#include "harness/cpu_features.h"
#include "harness/raster/row_step_avx2.h"
#include "harness/raster/row_step_avx512.h"

namespace vob {
namespace {

// The scalar loop: PolygonRaster's edge test (Edge::m, c, own) and DepthPlane::depth, term
// for term.
template <bool kOrtho>
int spans_scalar(const SampleFrame& fr, const RowEdges& e, const RowDepth& p, const RowSpan* spans,
                 int count, RowHits& hits) {
  int n = 0;
  for (int k = 0; k < count; ++k) {
    const int sy = spans[k].sy;
    const Vec3 row = fr.row_term(sy);
    for (int sx = spans[k].x0; sx <= spans[k].x1; ++sx) {
      const Vec3 x = row + fr.col_term(sx);
      bool in = true;
      for (int i = 0; i < 3; ++i) {
        const double v = e.c[i] + (e.mx[i] * x.x + e.my[i] * x.y + e.mz[i] * x.z);
        if (v < 0 || (v == 0 && !e.own[i])) in = false;
      }
      if (!in) continue;
      const double t = kOrtho ? -(dot(p.n, x) + p.d) * p.inv_nf : p.num / dot(p.n, x) * length(x);
      if ((kOrtho ? t >= 0 : t > 0) && std::isfinite(t)) hits.sx[n] = sx, hits.sy[n] = sy, hits.t[n++] = t;
    }
  }
  return n;
}

int run_scalar(const SampleFrame& fr, const RowEdges& e, const RowDepth& p, const RowSpan* spans, int count,
               RowHits& hits) {
  return fr.ortho() ? spans_scalar<true>(fr, e, p, spans, count, hits)
                    : spans_scalar<false>(fr, e, p, spans, count, hits);
}

// Four columns a step, no jump on the answers (row_step_avx2.h): every lane's depth is
// computed, the covered lanes are moved to the front and stored, and the count steps by
// their number. Lanes past x1 read the zero padding of SampleFrame's column arrays.
template <bool kOrtho>
__attribute__((target("avx2,popcnt"))) int spans_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p,
                                               const RowSpan* spans, int count, RowHits& hits) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const RowStepAvx2 k(e, p);
  int n = 0;
  for (int s = 0; s < count; ++s) {
    const int sy = spans[s].sy, x1 = spans[s].x1;
    const Vec3 row = fr.row_term(sy);
    const __m256d rx = _mm256_set1_pd(row.x), ry = _mm256_set1_pd(row.y), rz = _mm256_set1_pd(row.z);
    const __m128i sy4 = _mm_set1_epi32(sy);
    for (int sx = spans[s].x0; sx <= x1; sx += 4) {
      __m256d t;
      const int mask = k.step<kOrtho>(rx, ry, rz, cx, cy, cz, sx, x1, t);
      _mm256_storeu_pd(hits.t + n, RowStepAvx2::compact_t(t, mask));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(hits.sx + n),
                       _mm_add_epi32(_mm_set1_epi32(sx), RowStepAvx2::compact_lanes(mask)));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(hits.sy + n), sy4);
      n += __builtin_popcount(mask);
    }
  }
  return n;
}

int run_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p, const RowSpan* spans, int count,
             RowHits& hits) {
  return fr.ortho() ? spans_avx2<true>(fr, e, p, spans, count, hits)
                    : spans_avx2<false>(fr, e, p, spans, count, hits);
}

// Eight lanes a step: the spans cut into runs of up to four samples, two runs a step
// (lanes 0-3 the first, 4-7 the second), so that the short spans of small faces (about four
// samples on the helices) fill the lanes; hits in the runs' order, as the AVX2 kernel's.
template <bool kOrtho>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,popcnt"))) int spans_avx512(const SampleFrame& fr,
                                                                                   const RowEdges& e,
                                                                                   const RowDepth& p,
                                                                                   const RowSpan* spans, int count,
                                                                                   RowHits& hits) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const RowStepAvx512 k(e, p);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
  int n = 0, s = 0, sx = count > 0 ? spans[0].x0 : 0;
  // The next run: row sy, columns [x0, x0 + 4) cut at the span's end (lanes `bits`).
  const auto next_run = [&](int& sy, int& x0, unsigned& bits) {
    if (s == count) return false;
    sy = spans[s].sy, x0 = sx;
    const int last = std::min(spans[s].x1, sx + 3);
    bits = (1u << (last - sx + 1)) - 1;
    if (last == spans[s].x1) {
      if (++s < count) sx = spans[s].x0;
    } else {
      sx += 4;
    }
    return true;
  };
  int ya, xa, yb, xb;
  unsigned ba, bb;
  while (next_run(ya, xa, ba)) {
    const bool two = next_run(yb, xb, bb);
    if (!two) yb = ya, xb = xa, bb = 0;
    const Vec3 ra = fr.row_term(ya), rb = fr.row_term(yb);
    // Columns from xa and xb (SampleFrame pads its column arrays past the last column).
    const __m512d X = _mm512_add_pd(_mm512_mask_blend_pd(0xF0, _mm512_set1_pd(ra.x), _mm512_set1_pd(rb.x)),
                                    _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(cx + xa)), _mm256_loadu_pd(cx + xb), 1));
    const __m512d Y = _mm512_add_pd(_mm512_mask_blend_pd(0xF0, _mm512_set1_pd(ra.y), _mm512_set1_pd(rb.y)),
                                    _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(cy + xa)), _mm256_loadu_pd(cy + xb), 1));
    const __m512d Z = _mm512_add_pd(_mm512_mask_blend_pd(0xF0, _mm512_set1_pd(ra.z), _mm512_set1_pd(rb.z)),
                                    _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(cz + xa)), _mm256_loadu_pd(cz + xb), 1));
    __m512d t;
    __mmask8 inside;
    const __mmask8 mask = k.step<kOrtho>(X, Y, Z, static_cast<__mmask8>(ba | bb << 4), t, inside);
    _mm512_storeu_pd(hits.t + n, _mm512_maskz_compress_pd(mask, t));
    const __m256i x = _mm256_add_epi32(_mm256_mask_blend_epi32(0xF0, _mm256_set1_epi32(xa), _mm256_set1_epi32(xb)), lane);
    const __m256i y = _mm256_mask_blend_epi32(0xF0, _mm256_set1_epi32(ya), _mm256_set1_epi32(yb));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(hits.sx + n), _mm256_maskz_compress_epi32(mask, x));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(hits.sy + n), _mm256_maskz_compress_epi32(mask, y));
    n += __builtin_popcount(mask);
  }
  return n;
}

int run_avx512(const SampleFrame& fr, const RowEdges& e, const RowDepth& p, const RowSpan* spans, int count,
               RowHits& hits) {
  return fr.ortho() ? spans_avx512<true>(fr, e, p, spans, count, hits)
                    : spans_avx512<false>(fr, e, p, spans, count, hits);
}

}  // namespace

RowCoverageFn row_coverage_baseline() { return &run_scalar; }
RowCoverageFn row_coverage_avx2() { return cpu_has_avx2() ? &run_avx2 : nullptr; }
RowCoverageFn row_coverage_avx512() { return cpu_has_avx512() ? &run_avx512 : nullptr; }

RowCoverageFn row_coverage() {
  return cpu_has_avx512() ? &run_avx512 : cpu_has_avx2() ? &run_avx2 : &run_scalar;
}

}  // namespace vob
