// The fused argsort (harness/sort/radix_argsort) against std::stable_sort at 1 and 2
// threads, and the centroid orderer against its semantics: ids stably sorted by the
// sortable bits of float(-key), key = eye distance or view depth of the cell centroid as
// stored (float, relative to the centroids' box centre).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "harness/bench/registry.h"
#include "harness/sort/radix_argsort.h"
#include "harness/sort/radix_sort.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::testing;

namespace {

std::vector<int32_t> stable_argsort(const std::vector<uint32_t>& keys) {
  std::vector<int32_t> ids(keys.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::stable_sort(ids.begin(), ids.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
  return ids;
}

// Ids by descending key, ties by id: the order the old KeySort path gave.
std::vector<int32_t> reference_order(const std::vector<double>& key) {
  std::vector<uint32_t> bits(key.size());
  for (size_t i = 0; i < key.size(); ++i) bits[i] = float_sort_key(static_cast<float>(-key[i]));
  return stable_argsort(bits);
}

}  // namespace

TEST(RadixArgsort, MatchesStableSortForEveryKeyRangeAndThreadCount) {
  std::mt19937 rng(5);
  RadixArgsort sort;  // one object reused across sizes, as an orderer does across frames
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    for (size_t n : {0u, 1u, 2u, 17u, 1000u, 70000u, 300000u}) {
      for (int bits : {0, 1, 5, 11, 12, 22, 23, 24, 27, 28, 31, 32}) {
        const uint32_t base = bits == 32 ? 0 : static_cast<uint32_t>(rng()) >> bits;  // no wrap
        const uint32_t span = bits == 32 ? 0xffffffffu : (bits == 0 ? 0 : (1u << bits) - 1);
        std::uniform_int_distribution<uint32_t> u(0, span);
        std::vector<uint32_t> keys(n);
        for (uint32_t& k : keys) k = base + (rng() % 8 == 0 ? span / 2 : u(rng));  // ties too
        std::vector<int32_t> got(n, -1);
        sort.sort(n, [&](size_t i) { return keys[i]; }, got.data());
        ASSERT_EQ(got, stable_argsort(keys)) << "threads " << threads << " n " << n << " bits " << bits;
      }
    }
  }
}

TEST(RadixArgsort, UsesFewPassesForNarrowRanges) {
  RadixArgsort sort;
  std::vector<int32_t> out(5000);
  sort.sort(out.size(), [](size_t i) { return uint32_t(0x40000000u + (i * 7919) % 2048); }, out.data());
  EXPECT_EQ(sort.passes(), 1);  // 11 bits above a common base: one pass
  sort.sort(out.size(), [](size_t) { return 7u; }, out.data());
  EXPECT_EQ(sort.passes(), 0);
  for (size_t i = 0; i < out.size(); ++i) ASSERT_EQ(out[i], static_cast<int32_t>(i));
}

TEST(Centroid, OrderEqualsStableSortOfFloatKeysAtOneAndTwoThreads) {
  // A regular block: many centroids share a distance, so ties decide much of the order.
  Scene s = Scene::from_mesh("block", tet_block(40, 30, 20, Vec3{-2, 1, 0.5}, 0.5));
  const std::vector<Vec3>& c = s.cell_centroids().points;
  const size_t n = c.size();
  // The orderer keeps the centroids as floats relative to their box centre (centroid_keys.h).
  Vec3 lo = c[0], hi = c[0];
  for (const Vec3& q : c)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
  const Vec3 origin = (lo + hi) * 0.5;
  std::vector<Vec3> stored(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec3 d = c[i] - origin;
    stored[i] = {float(d.x), float(d.y), float(d.z)};
  }
  for (const char* spec : {"centroid", "centroid:key=view"}) {
    const bool by_view = std::string(spec).find("view") != std::string::npos;
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      auto ours = make_orderer(spec);
      PhaseClock prep;
      const Scene own = s.fresh();
      ours->prepare(own, prep);
      for (bool ortho : {false, true}) {
        ViewOptions opt;
        opt.ortho = ortho;
        for (const Camera& view : fibonacci_views(s.bounds(), 6, opt)) {
          std::vector<double> key(n);
          for (size_t i = 0; i < n; ++i) {
            const Vec3 d = stored[i] - (view.eye - origin);
            key[i] = (by_view || view.ortho) ? dot(d, view.forward()) : length(d);
          }
          PhaseClock clock;
          ASSERT_EQ(ours->order(view, clock).order, reference_order(key))
              << spec << " threads " << threads << " ortho " << ortho;
        }
      }
    }
  }
}
