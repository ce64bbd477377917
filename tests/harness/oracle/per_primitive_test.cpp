// The oracle's per-primitive attribution (OracleOptions::per_primitive): counts per id that
// sum to violating_fragments, land on the primitives drawn too late, and change nothing
// else in the verdict.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

TEST(OraclePerPrimitive, SumsToViolatingFragmentsAndChangesNothingElse) {
  const int n = 4;
  const Scene scene = test::kuhn_block_scene(n);
  ViewOptions vo;
  vo.width = vo.height = 48;
  const Camera cam = fibonacci_view(scene.bounds(), 14, 3, vo);
  std::vector<int32_t> order = test::tet_block_exact_order(scene.mesh(), n, cam);
  const OracleResult exact = check_ordering(scene, cam, order, {.per_primitive = true});
  ASSERT_EQ(exact.violating_fragments_per_primitive.size(), scene.mesh().num_cells());
  EXPECT_EQ(std::accumulate(exact.violating_fragments_per_primitive.begin(),
                            exact.violating_fragments_per_primitive.end(), int64_t(0)), 0);
  std::reverse(order.begin(), order.end());
  const OracleResult plain = check_ordering(scene, cam, order);
  EXPECT_TRUE(plain.violating_fragments_per_primitive.empty());
  OracleOptions opt;
  opt.per_primitive = true;
  const OracleResult r = check_ordering(scene, cam, order, opt);
  ASSERT_GT(r.violating_fragments, 0);
  EXPECT_EQ(std::accumulate(r.violating_fragments_per_primitive.begin(), r.violating_fragments_per_primitive.end(),
                            int64_t(0)),
            r.violating_fragments);
  // Reversed, the first cell drawn (the front one) is never late; every example's late
  // primitive has a count.
  EXPECT_EQ(r.violating_fragments_per_primitive[order.front()], 0);
  for (const auto& e : r.examples) EXPECT_GT(r.violating_fragments_per_primitive[e["primitive"].get<int>()], 0);
  EXPECT_EQ(r.to_json(), plain.to_json());
}
