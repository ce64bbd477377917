#include "harness/raster/row_coverage.h"

#include <immintrin.h>

#include <cmath>

#include "harness/cpu_features.h"
#include "harness/raster/row_step_avx2.h"

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

}  // namespace

RowCoverageFn row_coverage_baseline() { return &run_scalar; }

RowCoverageFn row_coverage() { return cpu_has_avx2() ? &run_avx2 : &run_scalar; }

}  // namespace vob
