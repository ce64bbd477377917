#include "algorithms/centroid/centroid_keys.h"

#include "harness/cpu_features.h"

namespace vob {
namespace {

// One body, compiled twice (baseline and AVX2, inlined into each).
template <bool kByView>
inline __attribute__((always_inline)) void key_loop(CentroidArrays c, Vec3 eye, Vec3 f, size_t i0, size_t i1,
                                                    uint32_t* k) {
  for (size_t i = i0; i < i1; ++i) k[i - i0] = centroid_key<kByView>(c, eye, f, i);
}

template <bool kByView>
void run_baseline(CentroidArrays c, Vec3 eye, Vec3 f, size_t i0, size_t i1, uint32_t* k) {
  key_loop<kByView>(c, eye, f, i0, i1, k);
}

// AVX2 only: -mfma is not implied, so no multiply-add can be contracted here.
template <bool kByView>
__attribute__((target("avx2"))) void run_avx2(CentroidArrays c, Vec3 eye, Vec3 f, size_t i0, size_t i1, uint32_t* k) {
  key_loop<kByView>(c, eye, f, i0, i1, k);
}

}  // namespace

CentroidKeyRun centroid_key_run_baseline(bool by_view) {
  return by_view ? &run_baseline<true> : &run_baseline<false>;
}

CentroidKeyRun centroid_key_run(bool by_view) {
  if (!cpu_has_avx2()) return centroid_key_run_baseline(by_view);
  return by_view ? &run_avx2<true> : &run_avx2<false>;
}

}  // namespace vob
