// The radix sort against std::stable_sort, and vtk-centroid against centroid:key=view:
// both sort cells by the depth of their centre along the view direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "harness/bench/registry.h"
#include "harness/sort/radix_sort.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::testing;

namespace {

void expect_matches_stable_sort(std::vector<float> keys) {
  std::vector<int32_t> ids(keys.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<int32_t> want = ids;
  std::stable_sort(want.begin(), want.end(), [&](int32_t a, int32_t b) { return keys[a] < keys[b]; });
  std::vector<float> k = keys;
  std::vector<uint64_t> scratch;
  radix_sort_by_key(k, ids, scratch);
  ASSERT_EQ(ids, want);
  for (size_t i = 0; i < k.size(); ++i) ASSERT_EQ(k[i], keys[want[i]]) << i;
}

}  // namespace

TEST(RadixSort, MatchesStableSortOnRandomFloatsWithNegativesAndTies) {
  std::mt19937 rng(11);
  for (size_t n : {0u, 1u, 2u, 17u, 1000u, 100000u}) {
    std::vector<float> keys(n);
    std::uniform_real_distribution<float> u(-1e6f, 1e6f);
    std::uniform_int_distribution<int> tie(0, 9);
    for (float& k : keys) k = tie(rng) == 0 ? 42.5f : u(rng);  // ~10% share one key
    expect_matches_stable_sort(keys);
  }
}

TEST(RadixSort, CoversExtremeMagnitudesAndFewDistinctKeys) {
  std::mt19937 rng(3);
  std::vector<float> keys = {-INFINITY, INFINITY, -1e-38f, 1e-38f, -3.4e38f, 3.4e38f, 1e-45f, -1e-45f};
  std::uniform_int_distribution<int> pick(-3, 3);
  for (int i = 0; i < 5000; ++i) keys.push_back(static_cast<float>(pick(rng)) * 0.5f);
  expect_matches_stable_sort(keys);
  // One key everywhere: every pass is skipped, the input order stays.
  expect_matches_stable_sort(std::vector<float>(1000, -7.0f));
}

TEST(RadixSort, NegativeZeroSortsBeforePositiveZero) {
  // The key transform is a total order on the bits: -0 < +0 (std::sort calls them equal).
  std::vector<float> k = {0.0f, -0.0f};
  std::vector<int32_t> v = {0, 1};
  std::vector<uint64_t> scratch;
  radix_sort_by_key(k, v, scratch);
  EXPECT_EQ(v, (std::vector<int32_t>{1, 0}));
}

TEST(RadixSort, ArgsortDescending) {
  EXPECT_EQ(radix_argsort_descending({1.f, 3.f, -2.f, 3.f}), (std::vector<int32_t>{1, 3, 0, 2}));
}

TEST(VtkCentroid, AgreesWithCentroidViewKeyUpToTies) {
  Scene s = Scene::from_mesh("block", tet_block(5, 4, 3, Vec3{-2.5, 1, 0.25}, 0.7));
  auto vtk = make_orderer("vtk-centroid");
  auto ours = make_orderer("centroid:key=view");
  PhaseClock prep;
  const Scene for_vtk = s.fresh(), for_ours = s.fresh();
  vtk->prepare(for_vtk, prep);
  ours->prepare(for_ours, prep);
  const size_t n = s.num_primitives();
  std::vector<Vec3> centre(n);
  for (size_t c = 0; c < n; ++c) centre[c] = s.mesh().cell_centroid(c);
  const double scale = s.bounds().radius() * 8;  // bounds |eye| + |centre| for these views
  const double tol = 1e-5 * scale;               // float keys: ~1e-7 relative, generously
  for (bool ortho : {false, true}) {
    ViewOptions opt;
    opt.ortho = ortho;
    for (const Camera& view : fibonacci_views(s.bounds(), 14, opt)) {
      PhaseClock clock;
      const auto a = vtk->order(view, clock).order;
      const auto b = ours->order(view, clock).order;
      ASSERT_TRUE(is_permutation_of(a, n));
      ASSERT_TRUE(is_permutation_of(b, n));
      std::vector<double> depth(n);
      for (size_t c = 0; c < n; ++c) depth[c] = dot(centre[c] - view.eye, view.forward());
      for (size_t i = 1; i < n; ++i) {  // back to front: depth non-increasing
        ASSERT_LE(depth[a[i]], depth[a[i - 1]] + tol) << "vtk at " << i;
        ASSERT_LE(depth[b[i]], depth[b[i - 1]] + tol) << "centroid at " << i;
      }
      std::vector<int32_t> pa(n), pb(n);
      for (size_t i = 0; i < n; ++i) pa[a[i]] = pb[b[i]] = static_cast<int32_t>(i);
      int64_t disagree = 0;
      for (size_t x = 0; x < n; ++x)
        for (size_t y = x + 1; y < n; ++y)
          if (std::fabs(depth[x] - depth[y]) > tol) disagree += (pa[x] < pa[y]) != (pb[x] < pb[y]);
      EXPECT_EQ(disagree, 0);
    }
  }
}

// The centroids are stored as floats relative to their box centre: a small mesh far from
// the world origin keeps the key precision of one at the origin (world-space floats would
// round its centroids to ~0.06 at 1e6, coarser than its cells).
TEST(Centroid, AFarOffMeshSortsAsPreciselyAsOneAtTheOrigin) {
  const double h = 1e-3;
  Scene s = Scene::from_mesh("far block", tet_block(12, 10, 8, Vec3{1e6, -2e6, 5e5}, h));
  const size_t n = s.num_primitives();
  std::vector<Vec3> centre(n);
  for (size_t c = 0; c < n; ++c) centre[c] = s.mesh().cell_centroid(c);
  for (const char* spec : {"centroid", "centroid:key=view"}) {
    const bool by_view = std::string(spec).find("view") != std::string::npos;
    auto ours = make_orderer(spec);
    PhaseClock prep;
    const Scene own = s.fresh();
    ours->prepare(own, prep);
    for (const Camera& view : fibonacci_views(s.bounds(), 14)) {
      PhaseClock clock;
      const auto order = ours->order(view, clock).order;
      ASSERT_TRUE(is_permutation_of(order, n));
      std::vector<double> key(n);
      for (size_t c = 0; c < n; ++c)
        key[c] = by_view ? dot(centre[c] - view.eye, view.forward()) : length(centre[c] - view.eye);
      // Back to front up to the float key's own rounding (the eye is a few block sizes away).
      const double tol = 1e-6 * s.bounds().radius();
      for (size_t i = 1; i < n; ++i)
        ASSERT_LE(key[order[i]], key[order[i - 1]] + tol) << spec << " at " << i;
    }
  }
}
