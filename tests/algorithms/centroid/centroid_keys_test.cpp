// The centroid key kernels (the AVX2 one where the CPU has it, and the baseline one) give
// the bits of Vec3's dot and length of the stored (float) centroids rounded to float, cell
// for cell, on runs of every length
// and at unaligned starts (the vector loops' tails), ties and far-apart magnitudes included.
// (A multiply-add would change a double key's last bit, which float rounding hides almost
// always; the kernels exclude it by construction: AVX2 without FMA, -ffp-contract=off.)
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "algorithms/centroid/centroid_keys.h"
#include "algorithms/centroid/key_order.h"

namespace vob {
namespace {

TEST(CentroidKeys, KernelsGiveTheBitsOfDotAndLength) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-30, 30), e(-6, 6);
  const size_t n = 4099;
  std::vector<float> x(n), y(n), z(n);
  for (size_t i = 0; i < n; ++i) {
    const double s = std::pow(10.0, e(rng));  // magnitudes 1e-6 .. 1e6
    x[i] = float(u(rng) * s), y[i] = float(u(rng) * s), z[i] = float(u(rng) * s);
    if (i % 7 == 3) x[i] = x[i - 1], y[i] = y[i - 1], z[i] = z[i - 1];  // ties
  }
  const CentroidArrays c{x.data(), y.data(), z.data()};
  std::vector<uint32_t> got(n);
  for (int v = 0; v < 4; ++v) {
    const Vec3 eye{u(rng), u(rng), u(rng)};
    const Vec3 f = normalize(Vec3{u(rng), u(rng), u(rng)});
    for (bool by_view : {false, true}) {
      for (CentroidKeyRun run : {centroid_key_run(by_view), centroid_key_run_baseline(by_view)}) {
        for (size_t i0 = 0; i0 < n;) {  // runs of 1 to 300 keys
          const size_t i1 = std::min(n, i0 + 1 + (i0 * 37) % 300);
          run(c, eye, f, i0, i1, got.data() + i0);
          i0 = i1;
        }
        for (size_t i = 0; i < n; ++i) {
          const Vec3 d = Vec3{x[i], y[i], z[i]} - eye;
          ASSERT_EQ(got[i], descending_key_bits(by_view ? dot(d, f) : length(d))) << i << " view " << by_view;
        }
      }
    }
  }
}

}  // namespace
}  // namespace vob
