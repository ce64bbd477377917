// radix_sort_by_key64: a stable sort by double keys, with or without kept buffers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

std::vector<int32_t> stable_order(const std::vector<double>& keys) {
  std::vector<int32_t> want(keys.size());
  std::iota(want.begin(), want.end(), 0);
  std::stable_sort(want.begin(), want.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
  return want;
}

TEST(RadixSort64, MatchesStableSortWithOneScratchOverGrowingAndShrinkingSizes) {
  std::mt19937 rng(5);
  Radix64Scratch scratch;
  for (size_t n : {1000u, 0u, 1u, 2u, 70000u, 17u, 3000u}) {
    std::vector<double> keys(n);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    std::uniform_int_distribution<int> pick(0, 19);
    for (double& k : keys) {
      const int p = pick(rng);
      // Ties, keys one ulp apart, infinities and the extremes among ordinary keys.
      k = p == 0 ? 0.25 : p == 1 ? std::nextafter(0.25, 1.0) : p == 2 ? -INFINITY : p == 3 ? 1e-300 : u(rng);
    }
    std::vector<int32_t> ids(n);
    std::iota(ids.begin(), ids.end(), 0);
    std::vector<double> k = keys;
    radix_sort_by_key64(k, ids, scratch);
    ASSERT_EQ(ids, stable_order(keys)) << n;
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(k[i], keys[ids[i]]) << i;
  }
}

TEST(RadixSort64, KeepsTheCallersValuesAndPutsNegativeZeroFirst) {
  std::vector<double> k = {0.0, -0.0, -1.0};
  std::vector<int32_t> v = {7, 8, 9};  // not 0..n-1: the values travel with their keys
  radix_sort_by_key64(k, v);
  EXPECT_EQ(v, (std::vector<int32_t>{9, 8, 7}));
  EXPECT_TRUE(std::signbit(k[1]));
}

}  // namespace
}  // namespace vob
