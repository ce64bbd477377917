#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "harness/oracle/k_metric.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

namespace {

int64_t histogram_total(const OracleResult& r) {
  return std::accumulate(r.k_histogram.begin(), r.k_histogram.end(), int64_t(0));
}

}  // namespace

TEST(KCounter, FenwickAgreesWithQuadratic) {
  std::mt19937 rng(3);
  KCounter kc;
  for (int n : {1, 2, 10, 47, 48, 49, 100, 300}) {
    for (int rep = 0; rep < 5; ++rep) {
      std::vector<double> in(n), q(n);
      std::uniform_int_distribution<int> u(0, n / 2 + 1);  // many ties
      for (int i = 0; i < n; ++i) in[i] = u(rng), q[i] = in[i] + (rep % 2 ? 0.5 : 0.0);
      int brute = 0;
      for (int j = 0; j < n; ++j) {
        int k = 0;
        for (int i = 0; i < j; ++i) k += in[i] < q[j];
        brute = std::max(brute, k);
      }
      EXPECT_EQ(kc.max_k(in.data(), q.data(), n), brute) << "n=" << n;
    }
  }
  // Back to front: k = 0. Front to back: the last fragment moves past all the others.
  std::vector<double> d(200);
  std::iota(d.begin(), d.end(), 1.0);
  std::vector<double> r(d.rbegin(), d.rend());
  EXPECT_EQ(kc.max_k(r.data(), r.data(), 200), 0);
  EXPECT_EQ(kc.max_k(d.data(), d.data(), 200), 199);
  std::vector<double> ties(200, 1.0);  // equal depths are not "nearer"
  EXPECT_EQ(kc.max_k(ties.data(), ties.data(), 200), 0);
}

TEST(Oracle, ExactOrderOfATetBlockPasses) {
  const int n = 4;
  const Scene s = test::kuhn_block_scene(n);
  int views = 0;
  for (bool ortho : {false, true}) {
    ViewOptions vo;
    vo.width = vo.height = 64;
    vo.ortho = ortho;
    for (const Camera& cam : fibonacci_views(s.bounds(), 7, vo)) {
      const auto order = test::tet_block_exact_order(s.mesh(), n, cam);
      ASSERT_EQ(order.size(), s.num_primitives());
      for (int S : {1, 2}) {
        OracleOptions o;
        o.supersample = S;
        const OracleResult r = check_ordering(s, cam, order, o);
        EXPECT_TRUE(r.ok()) << r.to_json().dump();
        EXPECT_EQ(r.violating_pixels, 0);
        EXPECT_EQ(r.violating_pairs, 0);
        EXPECT_EQ(r.max_k, 0);
        EXPECT_EQ(r.samples, 64 * 64 * S * S);
        EXPECT_EQ(histogram_total(r), r.samples);
        EXPECT_GT(r.covered_pixels, r.samples / 10);
        EXPECT_GE(r.max_list, 4);
        EXPECT_TRUE(r.examples.empty());
      }
      ++views;
    }
  }
  EXPECT_EQ(views, 14);
}

TEST(Oracle, ReversedOrderIsFlagged) {
  const int n = 4;
  const Scene s = test::kuhn_block_scene(n);
  for (bool ortho : {false, true}) {
    ViewOptions vo;
    vo.width = vo.height = 64;
    vo.ortho = ortho;
    const Camera cam = fibonacci_view(s.bounds(), 14, 3, vo);
    auto order = test::tet_block_exact_order(s.mesh(), n, cam);
    const OracleResult exact = check_ordering(s, cam, order);
    std::reverse(order.begin(), order.end());
    const OracleResult r = check_ordering(s, cam, order);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.fragments, exact.fragments);
    EXPECT_EQ(r.covered_pixels, exact.covered_pixels);
    EXPECT_EQ(r.max_list, exact.max_list);
    // Front to back: every fragment but the first of a sample violates, with k = list - 1.
    EXPECT_EQ(r.violating_fragments, r.fragments - r.covered_pixels);
    EXPECT_EQ(r.max_k, r.max_list - 1);
    EXPECT_GT(r.violating_pixels, 0);
    EXPECT_GT(r.violating_pairs, 0);
    EXPECT_EQ(histogram_total(r), r.samples);
    EXPECT_GT(r.samples_with_k_above(2), 0);
    ASSERT_EQ(r.examples.size(), 5u);
    const auto& e = r.examples[0];
    EXPECT_GT(e["depth"][0].get<double>(), e["blocker_depth"][1].get<double>() - 1e-12);
  }
}

TEST(Oracle, OneSwapGivesKOne) {
  const int n = 3;
  const Scene s = test::kuhn_block_scene(n);
  ViewOptions vo;
  vo.width = vo.height = 48;
  const Camera cam = fibonacci_view(s.bounds(), 14, 5, vo);
  auto order = test::tet_block_exact_order(s.mesh(), n, cam);
  // Swap two face neighbours somewhere in the middle: only their shared samples break.
  const size_t mid = order.size() / 2;
  std::swap(order[mid], order[mid + 1]);
  const OracleResult r = check_ordering(s, cam, order);
  EXPECT_LE(r.max_k, 1);
  EXPECT_LE(r.violating_pairs, 1);
  EXPECT_EQ(r.violating_fragments, r.violating_pixels);
}

TEST(Oracle, TwoParallelTriangles) {
  TriangleSoup soup;
  soup.points = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}};
  soup.tris = {{0, 1, 2}, {3, 4, 5}};
  const Scene s = Scene::from_soup("two", soup);
  for (bool ortho : {false, true}) {
    Camera cam = test::test_camera({0.1, 0.05, 5}, {0, 0, 0}, 32, 32, ortho, 3.0);
    const OracleResult good = check_ordering(s, cam, {0, 1});
    EXPECT_TRUE(good.ok());
    EXPECT_GT(good.covered_pixels, 50);
    const OracleResult bad = check_ordering(s, cam, {1, 0});
    EXPECT_FALSE(bad.ok());
    EXPECT_EQ(bad.max_k, 1);
    EXPECT_EQ(bad.violating_pairs, 1);
    EXPECT_EQ(bad.examples[0]["primitive"], 0);
    EXPECT_EQ(bad.examples[0]["blocked_by"], 1);
    EXPECT_EQ(histogram_total(bad), bad.samples);
    // Coplanar duplicates tie: no violation either way.
    TriangleSoup twin = soup;
    twin.tris = {{0, 1, 2}, {0, 2, 1}};
    const Scene t = Scene::from_soup("twin", twin);
    EXPECT_TRUE(check_ordering(t, cam, {0, 1}).ok());
    EXPECT_TRUE(check_ordering(t, cam, {1, 0}).ok());
  }
}

TEST(Oracle, VoxelsInDistanceOrderPass) {
  VoxelGrid g;
  g.dims = {6, 5, 4};
  g.spacing = {1, 1, 1.5};
  g.values.assign(g.num_voxels(), 0.0f);
  for (size_t i = 0; i < g.values.size(); ++i) g.values[i] = float((i * 7) % 5);
  g.threshold = 0.5f;
  const Scene s = Scene::from_grid("vox", g);
  for (bool ortho : {false, true}) {
    ViewOptions vo;
    vo.width = vo.height = 48;
    vo.ortho = ortho;
    for (int v : {0, 4, 9}) {
      const Camera cam = fibonacci_view(s.bounds(), 14, v, vo);
      std::vector<int32_t> order = significant_voxels(g);
      std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
        return cam.depth(g.centre_of(a)) > cam.depth(g.centre_of(b));
      });
      const OracleResult r = check_ordering(s, cam, order);
      EXPECT_TRUE(r.ok());
      EXPECT_GT(r.max_list, 2);
      std::reverse(order.begin(), order.end());
      const OracleResult bad = check_ordering(s, cam, order);
      EXPECT_FALSE(bad.ok());
      EXPECT_GT(bad.max_k, 1);
      EXPECT_EQ(histogram_total(bad), bad.samples);
    }
  }
}

TEST(Oracle, BadOrdersThrow) {
  const Scene s = test::kuhn_block_scene(2);
  const Camera cam = fibonacci_view(s.bounds(), 14, 0);
  EXPECT_THROW(check_ordering(s, cam, {0, 1, int32_t(s.num_primitives())}), InputError);
  EXPECT_THROW(check_ordering(s, cam, {-1}), InputError);
  OracleOptions o;
  o.supersample = 0;
  EXPECT_THROW(check_ordering(s, cam, {0}, o), InputError);
  VoxelGrid g;
  g.dims = {2, 1, 1};
  g.values = {1.0f, 0.0f};
  g.threshold = 0.5f;
  const Scene v = Scene::from_grid("vox", g);
  EXPECT_NO_THROW(check_ordering(v, cam, {0}));
  EXPECT_THROW(check_ordering(v, cam, {1}), InputError);  // not significant
  // Missing ids are simply not drawn.
  const OracleResult r = check_ordering(s, cam, {});
  EXPECT_EQ(r.fragments, 0);
  EXPECT_TRUE(r.ok());
}
