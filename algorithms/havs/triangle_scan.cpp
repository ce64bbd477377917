#include "algorithms/havs/triangle_scan.h"

#include <immintrin.h>

#include "harness/cpu_features.h"

namespace vob::havs {

void TriangleScan::row_ranges(int ya, int ny, const SampleRect& clip, int* p0, int* p1, int* c0, int* c1,
                              bool scalar) const {
  if (special_) return row_ranges_any(ya, ny, clip, p0, p1, c0, c1);
  if (cpu_has_avx2() && !scalar) return row_ranges_slanted_avx2(ya, ny, clip, p0, p1, c0, c1);
  row_ranges_slanted(ya, ny, clip, p0, p1, c0, c1);
}

// Lane j is row ya + r + j; every double operation is row_ranges_slanted's, in its order,
// and min/max take their operands in std::min/std::max's order. Rows past ny are computed
// and stored too (the arrays hold kRows, a multiple of 4) but never read.
__attribute__((target("avx2"))) void TriangleScan::row_ranges_slanted_avx2(int ya, int ny, const SampleRect& clip,
                                                                           int* p0, int* p1, int* c0, int* c1) const {
  static_assert(kRows % 4 == 0);
  const int lim = frame_->cols();
  const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256d neg_inf = _mm256_set1_pd(-std::numeric_limits<double>::infinity());
  const __m256d half = _mm256_set1_pd(0.5);
  // floor_near's clamp and shift
  const __m256d clamp_lo = _mm256_set1_pd(-double(lim) - 4.0), clamp_hi = _mm256_set1_pd(double(lim) + 2.0);
  const double off = double(lim) + 8.0;
  const __m256d voff = _mm256_set1_pd(off);
  const __m128i ioff = _mm_set1_epi32(int(off));
  const auto floor_near4 = [&](__m256d v) __attribute__((target("avx2"))) {
    const __m256d c = _mm256_min_pd(clamp_hi, _mm256_max_pd(clamp_lo, v));
    return _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_add_pd(c, voff)), ioff);
  };
  const __m128i x0 = _mm_set1_epi32(clip.x0), x1 = _mm_set1_epi32(clip.x1), one = _mm_set1_epi32(1);
  const __m128i zero = _mm_setzero_si128(), lanes = _mm_setr_epi32(0, 1, 2, 3);
  for (int r = 0; r < ny; r += 4) {
    const __m256d y = _mm256_add_pd(_mm256_cvtepi32_pd(_mm_add_epi32(_mm_set1_epi32(ya + r), lanes)), half);
    __m256d u_pos = inf, u_neg = inf, w_pos = neg_inf, w_neg = neg_inf;
    for (int i = 0; i < 3; ++i) {
      const Rows& e = row_;
      const __m256d sy = _mm256_mul_pd(_mm256_set1_pd(e.slope[i]), y);
      const __m256d lo = _mm256_sub_pd(_mm256_set1_pd(e.lo0[i]), sy), hi = _mm256_sub_pd(_mm256_set1_pd(e.hi0[i]), sy);
      const __m256d slack = _mm256_set1_pd(e.slack[i]);
      const __m256d u = _mm256_mul_pd(_mm256_set1_pd(-e.sign[i]), _mm256_sub_pd(_mm256_sub_pd(lo, slack), half));
      const __m256d w = _mm256_mul_pd(_mm256_set1_pd(e.sign[i]), _mm256_sub_pd(_mm256_add_pd(hi, slack), half));
      const __m256d off_pos = _mm256_set1_pd(e.off_pos[i]), off_neg = _mm256_set1_pd(e.off_neg[i]);
      // std::min(a, b) is (b < a ? b : a), _mm256_min_pd(b, a); likewise max.
      u_pos = _mm256_min_pd(_mm256_add_pd(u, off_pos), u_pos);
      u_neg = _mm256_min_pd(_mm256_add_pd(u, off_neg), u_neg);
      w_pos = _mm256_max_pd(_mm256_sub_pd(w, off_pos), w_pos);
      w_neg = _mm256_max_pd(_mm256_sub_pd(w, off_neg), w_neg);
    }
    const __m128i a = _mm_max_epi32(x0, _mm_sub_epi32(zero, floor_near4(u_pos)));
    const __m128i b = _mm_min_epi32(x1, floor_near4(u_neg));
    const __m128i c = _mm_max_epi32(x0, _mm_add_epi32(floor_near4(w_pos), one));
    const __m128i d = _mm_min_epi32(x1, _mm_sub_epi32(zero, _mm_add_epi32(floor_near4(w_neg), one)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p0 + r), a);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p1 + r), b);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(c0 + r), c);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(c1 + r), d);
  }
}

// Lane i is edge i (lane 3 repeats edge 0 and is stored but never read). Every double
// operation is setup's scalar loop's, in its order; a negation is the sign bit flipped (as
// the scalar negation is exact), std::isfinite is |x| < inf (false for NaN), and the
// selects on a > 0 are blends on the same comparison.
__attribute__((target("avx2"))) void TriangleScan::rows_avx2(double ymax) {
  const PolygonRaster::Edge* e = e_;
  const __m256d a = _mm256_setr_pd(e[0].a, e[1].a, e[2].a, e[0].a);
  const __m256d b = _mm256_setr_pd(e[0].b, e[1].b, e[2].b, e[0].b);
  const __m256d k = _mm256_setr_pd(e[0].k, e[1].k, e[2].k, e[0].k);
  const __m256d eta = _mm256_setr_pd(e[0].eta, e[1].eta, e[2].eta, e[0].eta);
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), neg0 = _mm256_set1_pd(-0.0);
  const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const auto fabs4 = [&](__m256d x) __attribute__((target("avx2"))) { return _mm256_andnot_pd(neg0, x); };
  const auto finite4 = [&](__m256d x) __attribute__((target("avx2"))) {
    return _mm256_cmp_pd(fabs4(x), inf, _CMP_LT_OQ);
  };
  const __m256d flat = _mm256_cmp_pd(a, zero, _CMP_EQ_OQ);
  const __m256d inv_a = _mm256_div_pd(one, a);
  const __m256d slope = _mm256_mul_pd(b, inv_a);
  const __m256d lo0 = _mm256_mul_pd(_mm256_sub_pd(_mm256_xor_pd(eta, neg0), k), inv_a);
  const __m256d hi0 = _mm256_mul_pd(_mm256_sub_pd(eta, k), inv_a);
  const __m256d finite = _mm256_and_pd(_mm256_and_pd(finite4(slope), finite4(lo0)), finite4(hi0));
  const __m256d sum = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fabs4(b), _mm256_set1_pd(ymax)), fabs4(k)), eta);
  const __m256d slack = _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(1e-12), sum), fabs4(inv_a)),
                                      _mm256_set1_pd(1e-9));
  const __m256d pos = _mm256_cmp_pd(a, zero, _CMP_GT_OQ);
  _mm256_storeu_pd(row_.slope, slope);
  _mm256_storeu_pd(row_.lo0, lo0);
  _mm256_storeu_pd(row_.hi0, hi0);
  _mm256_storeu_pd(row_.slack, _mm256_blendv_pd(_mm256_xor_pd(slack, neg0), slack, pos));
  _mm256_storeu_pd(row_.sign, _mm256_blendv_pd(_mm256_set1_pd(-1.0), one, pos));
  _mm256_storeu_pd(row_.off_pos, _mm256_blendv_pd(inf, zero, pos));
  _mm256_storeu_pd(row_.off_neg, _mm256_blendv_pd(zero, inf, pos));
  const int flat_bits = _mm256_movemask_pd(flat) & 7, finite_bits = _mm256_movemask_pd(finite) & 7;
  for (int i = 0; i < 3; ++i) row_.flat[i] = flat_bits >> i & 1, row_.finite[i] = finite_bits >> i & 1;
  // As the scalar loop: some edge flat, or some edge not flat and not finite.
  special_ = flat_bits != 0 || (~flat_bits & ~finite_bits & 7) != 0;
}

}  // namespace vob::havs
