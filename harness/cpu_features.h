// What this CPU can run, asked once per process: the kernels with AVX2 lanes pick their
// loop by it at run time, since the build targets baseline x86-64.
#pragma once

namespace vob {

inline bool cpu_has_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

}  // namespace vob
