// The oracle's split of violations under the gl rule (harness/oracle/rule_cycles.h): two
// triangles crossing each other are a cycle of the pixel precedence graph, which every
// order breaks somewhere. The order breaking it where it covers fewer pixels passes; the
// other one (excess), and an order drawing a triangle behind both last (avoidable), fail.
#include <gtest/gtest.h>

#include <vector>

#include "harness/oracle/oracle.h"

using namespace vob;

namespace {

Scene crossing() {
  TriangleSoup s;
  // A: z = 0.3 x; B: z = 0.12 - 0.3 x (in front of A where x < 0.2); C: behind both.
  s.points = {{-1, -1, -0.3}, {1, -1, 0.3},  {0, 1, 0},     {-1, -1, 0.42}, {1, -1, -0.18},
              {0, 1, 0.12},   {-2, -2, -1}, {2, -2, -1}, {0, 2, -1}};
  s.tris = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return Scene::from_soup("crossing", s);
}

Camera above() {
  Camera c;
  c.eye = {0.05, 0.1, 6};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fov_deg = 40;
  c.width = c.height = 96;
  return c;
}

OracleResult judge(const Scene& s, std::vector<int32_t> order, RasterRule rule = RasterRule::gl) {
  OracleOptions o;
  o.raster = rule;
  return check_ordering(s, above(), order, o);
}

}  // namespace

TEST(OracleGlCycles, OnlyTheFewestForcedViolationsPass) {
  const Scene s = crossing();
  const OracleResult best = judge(s, {2, 0, 1});  // A before B: violated where A is in front
  const OracleResult worse = judge(s, {2, 1, 0});
  ASSERT_TRUE(best.rule_cycles && worse.rule_cycles);
  EXPECT_GT(best.violating_pixels, 0);
  EXPECT_GT(worse.violating_pixels, best.violating_pixels);
  EXPECT_EQ(best.rule_cycles->components, 1);
  EXPECT_EQ(best.rule_cycles->largest, 2);
  EXPECT_EQ(best.rule_cycles->avoidable_fragments, 0);
  EXPECT_EQ(best.rule_cycles->excess, 0);
  EXPECT_EQ(best.rule_cycles->cycle_pixels, best.violating_pixels);
  EXPECT_EQ(best.rule_cycles->forced_pairs, best.violating_fragments);
  EXPECT_TRUE(best.ok()) << best.to_json().dump();
  // The deliberately wrong orders are still caught.
  EXPECT_EQ(worse.rule_cycles->excess, worse.violating_fragments - best.violating_fragments);
  EXPECT_FALSE(worse.ok());
  const OracleResult behind_last = judge(s, {0, 1, 2});
  ASSERT_TRUE(behind_last.rule_cycles);
  EXPECT_GT(behind_last.rule_cycles->avoidable_fragments, 0);
  EXPECT_GT(behind_last.rule_cycles->avoidable_pixels, 0);
  EXPECT_FALSE(behind_last.ok());
  // The exact rule has no such split: any violation fails.
  const OracleResult exact = judge(s, {2, 0, 1}, RasterRule::exact);
  EXPECT_FALSE(exact.rule_cycles.has_value());
  EXPECT_FALSE(exact.ok());
}
