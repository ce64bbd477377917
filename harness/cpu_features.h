// What this CPU can run, asked once per process: the kernels with AVX2 or AVX-512 lanes
// pick their loop by it at run time, since the build targets baseline x86-64.
#pragma once

namespace vob {

inline bool cpu_has_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

// The AVX-512 kernels' subset (F, VL, DQ), with AVX2 for the parts they share.
inline bool cpu_has_avx512() {
  static const bool yes = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                          __builtin_cpu_supports("avx512dq") && cpu_has_avx2();
  return yes;
}

}  // namespace vob
