// One step of the exact rule's AVX2 row kernel: four samples of a row against a triangle's
// three edges and its depth plane. Shared by the row kernel (row_coverage.cpp) and SXMPVO's
// tiny-face entries (algorithms/sxmpvo/tiny_faces.cpp), so that both give the scalar loop's
// samples and t bits. Include it only from files built with -ffp-contract=off, and call it
// only from functions with target("avx2") (it has no FMA: each lane rounds as the scalar
// double does).
#pragma once
#include <immintrin.h>

#include <cmath>
#include <cstdint>

#include "harness/raster/row_coverage.h"

namespace vob {

// Lane orders that move the set lanes of a 4-bit mask to the front, in order: as lane
// numbers (for 32-bit values) and as pairs of 32-bit halves (for doubles).
struct LaneCompaction {
  int32_t lanes[16][4];
  int32_t halves[16][8];
  LaneCompaction() {
    for (int m = 0; m < 16; ++m) {
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (m & (1 << j)) lanes[m][k] = j, halves[m][2 * k] = 2 * j, halves[m][2 * k + 1] = 2 * j + 1, ++k;
      for (; k < 4; ++k) lanes[m][k] = 0, halves[m][2 * k] = 0, halves[m][2 * k + 1] = 1;
    }
  }
};
inline const LaneCompaction kLaneCompaction;

struct RowStepAvx2 {
  __m256d mx[3], my[3], mz[3], c[3], disown[3];
  __m256d nx, ny, nz, d, num, inv_nf;

  __attribute__((target("avx2"))) RowStepAvx2(const RowEdges& e, const RowDepth& p) {
    for (int i = 0; i < 3; ++i) {
      mx[i] = _mm256_set1_pd(e.mx[i]), my[i] = _mm256_set1_pd(e.my[i]), mz[i] = _mm256_set1_pd(e.mz[i]);
      c[i] = _mm256_set1_pd(e.c[i]);
      disown[i] = _mm256_castsi256_pd(_mm256_set1_epi64x(e.own[i] ? 0 : -1));
    }
    nx = _mm256_set1_pd(p.n.x), ny = _mm256_set1_pd(p.n.y), nz = _mm256_set1_pd(p.n.z);
    d = _mm256_set1_pd(p.d), num = _mm256_set1_pd(p.num), inv_nf = _mm256_set1_pd(p.inv_nf);
  }

  // Columns sx .. sx+3 of the row whose term is (rx, ry, rz), from SampleFrame's padded
  // column arrays; lanes past x1 are masked off. Returns the mask of covered samples (bit j:
  // column sx + j) and their t.
  template <bool kOrtho>
  __attribute__((target("avx2"))) int step(__m256d rx, __m256d ry, __m256d rz, const double* cx, const double* cy,
                                           const double* cz, int sx, int x1, __m256d& t) const {
    int inside;
    return step<kOrtho>(rx, ry, rz, cx, cy, cz, sx, x1, t, inside);
  }
  // The same, and in `inside` the lanes the edge tests accept. The returned mask is
  // `inside` less the lanes whose t is not positive and finite, so a caller may place its
  // entries by `inside`, known long before t (which waits on a division and a square root),
  // and redo the rare step where the two differ.
  template <bool kOrtho>
  __attribute__((target("avx2"))) int step(__m256d rx, __m256d ry, __m256d rz, const double* cx, const double* cy,
                                           const double* cz, int sx, int x1, __m256d& t, int& inside) const {
    const __m256d zero = _mm256_setzero_pd(), sign = _mm256_set1_pd(-0.0);
    const __m256d X = _mm256_add_pd(rx, _mm256_loadu_pd(cx + sx));
    const __m256d Y = _mm256_add_pd(ry, _mm256_loadu_pd(cy + sx));
    const __m256d Z = _mm256_add_pd(rz, _mm256_loadu_pd(cz + sx));
    // Rejected: v < 0, or v == 0 on an edge the sample does not own (NaN rejects nothing).
    __m256d out = _mm256_cmp_pd(_mm256_set_pd(3, 2, 1, 0), _mm256_set1_pd(double(x1 - sx)), _CMP_GT_OQ);
    for (int i = 0; i < 3; ++i) {
      const __m256d dotm = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(mx[i], X), _mm256_mul_pd(my[i], Y)),
                                         _mm256_mul_pd(mz[i], Z));
      const __m256d v = _mm256_add_pd(c[i], dotm);
      out = _mm256_or_pd(out, _mm256_cmp_pd(v, zero, _CMP_LT_OQ));
      out = _mm256_or_pd(out, _mm256_and_pd(_mm256_cmp_pd(v, zero, _CMP_EQ_OQ), disown[i]));
    }
    const __m256d nX =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, X), _mm256_mul_pd(ny, Y)), _mm256_mul_pd(nz, Z));
    __m256d ok;
    if (kOrtho) {
      t = _mm256_mul_pd(_mm256_xor_pd(_mm256_add_pd(nX, d), sign), inv_nf);
      ok = _mm256_cmp_pd(t, zero, _CMP_GE_OQ);
    } else {
      const __m256d xx =
          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(X, X), _mm256_mul_pd(Y, Y)), _mm256_mul_pd(Z, Z));
      t = _mm256_mul_pd(_mm256_div_pd(num, nX), _mm256_sqrt_pd(xx));
      ok = _mm256_cmp_pd(t, zero, _CMP_GT_OQ);
    }
    const __m256d inf = _mm256_set1_pd(HUGE_VAL);
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_andnot_pd(sign, t), inf, _CMP_LT_OQ));  // finite
    inside = ~_mm256_movemask_pd(out) & 15;
    return _mm256_movemask_pd(_mm256_andnot_pd(out, ok));
  }

  // The covered lanes' t moved to the front (in lane order).
  __attribute__((target("avx2"))) static __m256d compact_t(__m256d t, int mask) {
    const __m256i halves = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kLaneCompaction.halves[mask]));
    return _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(t), halves));
  }
  // The covered lanes' numbers (0..3) moved to the front.
  __attribute__((target("avx2"))) static __m128i compact_lanes(int mask) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(kLaneCompaction.lanes[mask]));
  }
};

}  // namespace vob
