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
      const Row& e = row_[i];
      const __m256d sy = _mm256_mul_pd(_mm256_set1_pd(e.slope), y);
      const __m256d lo = _mm256_sub_pd(_mm256_set1_pd(e.lo0), sy), hi = _mm256_sub_pd(_mm256_set1_pd(e.hi0), sy);
      const __m256d slack = _mm256_set1_pd(e.slack);
      const __m256d u = _mm256_mul_pd(_mm256_set1_pd(-e.sign), _mm256_sub_pd(_mm256_sub_pd(lo, slack), half));
      const __m256d w = _mm256_mul_pd(_mm256_set1_pd(e.sign), _mm256_sub_pd(_mm256_add_pd(hi, slack), half));
      const __m256d off_pos = _mm256_set1_pd(e.off_pos), off_neg = _mm256_set1_pd(e.off_neg);
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

}  // namespace vob::havs
