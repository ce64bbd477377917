// RadixArgsort's two-level path (ranges of 23 to 27 bits, and of 17 to 22 bits from 2^17
// keys on: one scatter by the top digit, then each bucket by its low bits in cache) against
// std::stable_sort: clustered keys (a few
// huge buckets, many empty), buckets around the insertion-sort size, the edges of the
// range where the path is taken, at 1 and 2 threads; and float view depths as the centroid
// orderer makes them.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "harness/sort/radix_argsort.h"
#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

std::vector<int32_t> stable_argsort(const std::vector<uint32_t>& keys) {
  std::vector<int32_t> ids(keys.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::stable_sort(ids.begin(), ids.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
  return ids;
}

void expect_sorted_like_stable(RadixArgsort& sort, const std::vector<uint32_t>& keys, const char* what) {
  std::vector<int32_t> got(keys.size(), -1);
  sort.sort(keys.size(), [&](size_t i) { return keys[i]; }, got.data());
  ASSERT_EQ(got, stable_argsort(keys)) << what << " n " << keys.size();
}

TEST(RadixTwoLevel, ClusteredKeysAndRangeEdges) {
  std::mt19937 rng(11);
  RadixArgsort sort;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    for (int bits : {23, 24, 27, 28}) {
      for (size_t n : {40u, 5000u, 200000u}) {
        const uint32_t span = (1u << bits) - 1, base = 0x1000u;
        std::normal_distribution<double> g(span / 2.0, span / 64.0);  // most keys in few buckets
        std::vector<uint32_t> keys(n);
        for (uint32_t& k : keys) k = base + uint32_t(std::clamp(g(rng), 0.0, double(span)));
        keys[0] = base, keys[n - 1] = base + span;  // the full range: this many bits
        if (n > 100) keys[n / 2] = keys[n / 3];     // an equal pair far apart
        expect_sorted_like_stable(sort, keys, "clustered");
        EXPECT_EQ(sort.passes(), 3) << bits;
      }
    }
    // 17 to 22 bits: the two-level path only from 2^17 keys on (odd and even low parts).
    for (int bits : {17, 18, 21, 22}) {
      for (size_t n : {5000u, 200000u}) {
        const uint32_t span = (1u << bits) - 1, base = 0xbf000000u;
        std::normal_distribution<double> g(span / 3.0, span / 16.0);
        std::vector<uint32_t> keys(n);
        for (uint32_t& k : keys) k = base + uint32_t(std::clamp(g(rng), 0.0, double(span)));
        keys[1] = base, keys[n - 2] = base + span;
        keys[n / 2] = keys[n / 5];
        expect_sorted_like_stable(sort, keys, "two digits");
        EXPECT_EQ(sort.passes(), n >= (1u << 17) ? 3 : 2) << bits << " n " << n;
      }
    }
  }
}

TEST(RadixTwoLevel, ViewDepthsAsTheCentroidOrdererSortsThem) {
  // ~1M-cell-like depth keys: float(-depth) of points on a slab, many equal after rounding.
  std::mt19937 rng(3);
  // (2, 9): three binades, ~24 bits; (17, 30): one binade, 22 bits, like view 1 of the 1M
  // helix (eye ~21 from its centre), the case that took two 11-bit scatters before.
  for (const auto& [lo, hi] : {std::pair{2.0, 9.0}, std::pair{17.0, 30.0}}) {
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<uint32_t> keys(300000);
    for (uint32_t& k : keys) k = float_sort_key(static_cast<float>(-u(rng)));
    RadixArgsort sort;
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      expect_sorted_like_stable(sort, keys, "depths");
      EXPECT_EQ(sort.passes(), 3) << lo;
    }
  }
}

}  // namespace
}  // namespace vob
