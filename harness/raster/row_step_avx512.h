// One step of the exact rule's row kernel in eight AVX-512 lanes: row_step_avx2.h's step,
// each lane the same operations in the same order (no FMA: include only from files built
// with -ffp-contract=off), so the same coverage and t bits as the scalar loop. Shared by
// the row kernel (row_coverage.cpp) and SXMPVO's tiny-face entries; call only from
// functions with target("avx512f,avx512vl,avx512dq,avx2").
#pragma once
#include <immintrin.h>

#include <cmath>

#include "harness/raster/edge_lanes_avx2.h"
#include "harness/raster/row_coverage.h"

namespace vob {

// A triangle's three edges and depth plane broadcast to eight lanes, and the step over them.
struct RowStepAvx512 {
  __m512d mx[3], my[3], mz[3], c[3];
  __mmask8 disown[3];
  __m512d nx, ny, nz, d, num, inv_nf;

  __attribute__((target("avx512f,avx512vl,avx512dq"))) RowStepAvx512(const RowEdges& e, const RowDepth& p) {
    for (int i = 0; i < 3; ++i) {
      mx[i] = _mm512_set1_pd(e.mx[i]), my[i] = _mm512_set1_pd(e.my[i]), mz[i] = _mm512_set1_pd(e.mz[i]);
      c[i] = _mm512_set1_pd(e.c[i]);
      disown[i] = e.own[i] ? 0 : 0xFF;
    }
    nx = _mm512_set1_pd(p.n.x), ny = _mm512_set1_pd(p.n.y), nz = _mm512_set1_pd(p.n.z);
    d = _mm512_set1_pd(p.d), num = _mm512_set1_pd(p.num), inv_nf = _mm512_set1_pd(p.inv_nf);
  }

  // From the edges in lanes (edge_lanes_avx2.h) without a trip through memory: lane i of
  // each edge vector broadcast; `own` bit i: edge i owns its exact zeros.
  __attribute__((target("avx512f,avx512vl,avx512dq,avx2"), always_inline)) RowStepAvx512(const avx2::EdgeLanes& l, int own,
                                                                                  const RowDepth& p) {
    for (int i = 0; i < 3; ++i) {
      const __m512i lane = _mm512_set1_epi64(i);
      mx[i] = _mm512_permutexvar_pd(lane, _mm512_castpd256_pd512(l.mx));
      my[i] = _mm512_permutexvar_pd(lane, _mm512_castpd256_pd512(l.my));
      mz[i] = _mm512_permutexvar_pd(lane, _mm512_castpd256_pd512(l.mz));
      c[i] = _mm512_permutexvar_pd(lane, _mm512_castpd256_pd512(l.c));
      disown[i] = (own >> i) & 1 ? 0 : 0xFF;
    }
    nx = _mm512_set1_pd(p.n.x), ny = _mm512_set1_pd(p.n.y), nz = _mm512_set1_pd(p.n.z);
    d = _mm512_set1_pd(p.d), num = _mm512_set1_pd(p.num), inv_nf = _mm512_set1_pd(p.inv_nf);
  }

  // Lanes `valid` of sample directions (X, Y, Z): the covered ones, and in `inside` those
  // the edge tests accept (t's tests aside).
  template <bool kOrtho>
  __attribute__((target("avx512f,avx512vl,avx512dq"), always_inline)) __mmask8 step(__m512d X, __m512d Y, __m512d Z,
                                                                                    __mmask8 valid, __m512d& t,
                                                                                    __mmask8& inside) const {
    const __m512d zero = _mm512_setzero_pd();
    __mmask8 in = valid;
    for (int i = 0; i < 3; ++i) {
      const __m512d dotm = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(mx[i], X), _mm512_mul_pd(my[i], Y)),
                                         _mm512_mul_pd(mz[i], Z));
      const __m512d v = _mm512_add_pd(c[i], dotm);
      in &= ~_mm512_cmp_pd_mask(v, zero, _CMP_LT_OQ);
      in &= ~(_mm512_cmp_pd_mask(v, zero, _CMP_EQ_OQ) & disown[i]);
    }
    const __m512d nX = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(nx, X), _mm512_mul_pd(ny, Y)), _mm512_mul_pd(nz, Z));
    __mmask8 ok;
    if (kOrtho) {
      t = _mm512_mul_pd(_mm512_xor_pd(_mm512_add_pd(nX, d), _mm512_set1_pd(-0.0)), inv_nf);
      ok = _mm512_cmp_pd_mask(t, zero, _CMP_GE_OQ);
    } else {
      const __m512d xx = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(X, X), _mm512_mul_pd(Y, Y)), _mm512_mul_pd(Z, Z));
      t = _mm512_mul_pd(_mm512_div_pd(num, nX), _mm512_sqrt_pd(xx));
      ok = _mm512_cmp_pd_mask(t, zero, _CMP_GT_OQ);
    }
    ok &= _mm512_cmp_pd_mask(_mm512_abs_pd(t), _mm512_set1_pd(HUGE_VAL), _CMP_LT_OQ);  // finite
    inside = in;
    return in & ok;
  }
};

}  // namespace vob
