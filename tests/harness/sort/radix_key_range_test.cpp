// RadixArgsort's range guess (make_keys' lo, hi: the key pass counts the top digit): a
// guess wider than the keys is used and sorts like std::stable_sort; a guess that some key
// falls outside of (below, above) or that does not ask for the two-level path is ignored
// and the sort is still right; at 1 and 2 threads. With one thread the key pass scatters
// into buckets sized from a sample; a sample that misjudges them makes it start over.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "harness/sort/radix_argsort.h"

namespace vob {
namespace {

std::vector<int32_t> sorted_with_guess(RadixArgsort& sort, const std::vector<uint32_t>& keys, uint32_t lo, uint32_t hi) {
  std::vector<int32_t> got(keys.size(), -1);
  sort.make_keys(keys.size(), [&](size_t i) { return keys[i]; }, lo, hi);
  sort.sort_keys(got.data());
  return got;
}

TEST(RadixKeyRange, GuessUsedOnlyWhenEveryKeyFallsInside) {
  std::mt19937 rng(5);
  const uint32_t base = 0xbf400000u, span = (1u << 22) - 1;
  std::normal_distribution<double> g(span / 2.0, span / 20.0);  // clustered: neighbours share buckets
  std::vector<uint32_t> keys(300000);
  for (uint32_t& k : keys) k = base + uint32_t(std::clamp(g(rng), 0.0, double(span)));
  keys[7] = base, keys[9] = base + span, keys[1000] = keys[200000];  // full range, a far tie
  std::vector<int32_t> want(keys.size());
  std::iota(want.begin(), want.end(), 0);
  std::stable_sort(want.begin(), want.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
  RadixArgsort sort;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    struct Case {
      uint32_t lo, hi;
      bool used;
    };
    for (const Case& c : {Case{base, base + span, true}, Case{base - 12345, base + span + 99999, true},
                          Case{base - (1u << 24), base + span, true},  // 25 bits: a wider top digit
                          Case{base + 1, base + span, false}, Case{base, base + span - 1, false},
                          Case{base - (1u << 28), base + span, false},  // too wide for two levels
                          Case{1, 0, false}}) {
      EXPECT_EQ(sorted_with_guess(sort, keys, c.lo, c.hi), want) << c.lo << " " << c.hi << " t" << threads;
      EXPECT_EQ(sort.counted_in_key_pass(), c.used) << c.lo << " " << c.hi;
      EXPECT_EQ(sort.scattered_in_key_pass(), c.used && threads == 1) << c.lo << " " << c.hi;
    }
  }
}

TEST(RadixKeyRange, SampleThatMisjudgesTheBucketsStartsOver) {
  // Every 32nd key (so every key of the sample, one in 32 or fewer) is the lowest; the rest
  // fill the top bucket, which the sample gave no room: the scatter overflows and the key pass starts over, counting.
  // 23 and 24 bits: rooms by the low 15 bits, 256 and 512 of them (the fallback's buckets by the low 16).
  for (const uint32_t span : {(1u << 23) - 1, (1u << 24) - 1}) {
    const uint32_t base = 0x40000000u;
    std::vector<uint32_t> keys(200000);
    for (size_t i = 0; i < keys.size(); ++i)
      keys[i] = i % 32 == 0 ? base : base + span - uint32_t(i % 1000) * 37;
    std::vector<int32_t> want(keys.size());
    std::iota(want.begin(), want.end(), 0);
    std::stable_sort(want.begin(), want.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    RadixArgsort sort;
    EXPECT_EQ(sorted_with_guess(sort, keys, base, base + span), want) << span;
    EXPECT_TRUE(sort.counted_in_key_pass());
    EXPECT_FALSE(sort.scattered_in_key_pass());
  }
}

}  // namespace
}  // namespace vob
