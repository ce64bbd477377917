#include "harness/raster/row_coverage.h"

#include <immintrin.h>

#include <cmath>

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

// Lane orders that move the set lanes of a 4-bit mask to the front, in order: as column
// offsets (for sx) and as pairs of 32-bit halves (for the doubles t).
struct Compaction {
  int32_t lanes[16][4];
  int32_t halves[16][8];
  Compaction() {
    for (int m = 0; m < 16; ++m) {
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (m & (1 << j)) lanes[m][k] = j, halves[m][2 * k] = 2 * j, halves[m][2 * k + 1] = 2 * j + 1, ++k;
      for (; k < 4; ++k) lanes[m][k] = 0, halves[m][2 * k] = 0, halves[m][2 * k + 1] = 1;
    }
  }
};
const Compaction kCompaction;

// Four columns a step, no jump on the answers: every lane's depth is computed, the covered
// lanes are moved to the front and stored, and the count steps by their number. Lanes past
// x1 read the zero padding of SampleFrame's column arrays and are masked off.
template <bool kOrtho>
__attribute__((target("avx2,popcnt"))) int spans_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p,
                                               const RowSpan* spans, int count, RowHits& hits) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const __m256d zero = _mm256_setzero_pd(), sign = _mm256_set1_pd(-0.0);
  const __m256d inf = _mm256_set1_pd(HUGE_VAL);
  __m256d mx[3], my[3], mz[3], c[3], disown[3];
  for (int i = 0; i < 3; ++i) {
    mx[i] = _mm256_set1_pd(e.mx[i]), my[i] = _mm256_set1_pd(e.my[i]), mz[i] = _mm256_set1_pd(e.mz[i]);
    c[i] = _mm256_set1_pd(e.c[i]);
    disown[i] = _mm256_castsi256_pd(_mm256_set1_epi64x(e.own[i] ? 0 : -1));
  }
  const __m256d nx = _mm256_set1_pd(p.n.x), ny = _mm256_set1_pd(p.n.y), nz = _mm256_set1_pd(p.n.z);
  const __m256d d = _mm256_set1_pd(p.d), num = _mm256_set1_pd(p.num), inv_nf = _mm256_set1_pd(p.inv_nf);
  const __m256d lane = _mm256_set_pd(3, 2, 1, 0);
  int n = 0;
  for (int k = 0; k < count; ++k) {
    const int sy = spans[k].sy, x1 = spans[k].x1;
    const Vec3 row = fr.row_term(sy);
    const __m256d rx = _mm256_set1_pd(row.x), ry = _mm256_set1_pd(row.y), rz = _mm256_set1_pd(row.z);
    const __m128i sy4 = _mm_set1_epi32(sy);
    for (int sx = spans[k].x0; sx <= x1; sx += 4) {
      const __m256d X = _mm256_add_pd(rx, _mm256_loadu_pd(cx + sx));
      const __m256d Y = _mm256_add_pd(ry, _mm256_loadu_pd(cy + sx));
      const __m256d Z = _mm256_add_pd(rz, _mm256_loadu_pd(cz + sx));
      // Rejected: v < 0, or v == 0 on an edge the sample does not own (NaN rejects nothing).
      __m256d out = _mm256_cmp_pd(lane, _mm256_set1_pd(double(x1 - sx)), _CMP_GT_OQ);
      for (int i = 0; i < 3; ++i) {
        const __m256d dotm = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(mx[i], X), _mm256_mul_pd(my[i], Y)), _mm256_mul_pd(mz[i], Z));
        const __m256d v = _mm256_add_pd(c[i], dotm);
        out = _mm256_or_pd(out, _mm256_cmp_pd(v, zero, _CMP_LT_OQ));
        out = _mm256_or_pd(out, _mm256_and_pd(_mm256_cmp_pd(v, zero, _CMP_EQ_OQ), disown[i]));
      }
      const __m256d nX = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, X), _mm256_mul_pd(ny, Y)),
                                       _mm256_mul_pd(nz, Z));
      __m256d t, ok;
      if (kOrtho) {
        t = _mm256_mul_pd(_mm256_xor_pd(_mm256_add_pd(nX, d), sign), inv_nf);
        ok = _mm256_cmp_pd(t, zero, _CMP_GE_OQ);
      } else {
        const __m256d xx = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(X, X), _mm256_mul_pd(Y, Y)),
                                         _mm256_mul_pd(Z, Z));
        t = _mm256_mul_pd(_mm256_div_pd(num, nX), _mm256_sqrt_pd(xx));
        ok = _mm256_cmp_pd(t, zero, _CMP_GT_OQ);
      }
      ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_andnot_pd(sign, t), inf, _CMP_LT_OQ));  // finite
      const int mask = _mm256_movemask_pd(_mm256_andnot_pd(out, ok));
      const __m256i halves = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kCompaction.halves[mask]));
      const __m128i lanes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(kCompaction.lanes[mask]));
      _mm256_storeu_pd(hits.t + n, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(t), halves)));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(hits.sx + n), _mm_add_epi32(_mm_set1_epi32(sx), lanes));
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

}  // namespace

bool row_coverage_uses_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

RowCoverageFn row_coverage_baseline() { return &run_scalar; }

RowCoverageFn row_coverage() { return row_coverage_uses_avx2() ? &run_avx2 : &run_scalar; }

}  // namespace vob
