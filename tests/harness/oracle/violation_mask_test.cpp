// The oracle's violation mask (OracleOptions::violation_mask) and the violation map drawn
// from it: the marked pixels are exactly the violating pixels the verdict counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "harness/oracle/oracle.h"
#include "harness/render/compositor.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

namespace {

int64_t ones(const std::vector<uint8_t>& m) { return std::count(m.begin(), m.end(), uint8_t(1)); }

struct Case {
  Scene scene;
  Camera cam;
  std::vector<int32_t> reversed;
};

Case reversed_block(int size) {
  const int n = 4;
  Case c{test::kuhn_block_scene(n), {}, {}};
  ViewOptions vo;
  vo.width = vo.height = size;
  c.cam = fibonacci_view(c.scene.bounds(), 14, 3, vo);
  c.reversed = test::tet_block_exact_order(c.scene.mesh(), n, c.cam);
  std::reverse(c.reversed.begin(), c.reversed.end());
  return c;
}

}  // namespace

TEST(ViolationMask, OnlyWhenAsked) {
  const Case c = reversed_block(40);
  const OracleResult r = check_ordering(c.scene, c.cam, c.reversed);
  EXPECT_TRUE(r.violation_mask.empty());
  EXPECT_GT(r.violating_pixels, 0);
}

TEST(ViolationMask, CountsViolatingPixelsAtS1) {
  const Case c = reversed_block(40);
  OracleOptions o;
  o.violation_mask = true;
  const OracleResult r = check_ordering(c.scene, c.cam, c.reversed, o);
  ASSERT_EQ(r.mask_width, 40);
  ASSERT_EQ(r.mask_height, 40);
  ASSERT_EQ(r.violation_mask.size(), 1600u);
  EXPECT_GT(r.violating_pixels, 0);
  EXPECT_EQ(ones(r.violation_mask), r.violating_pixels);
  // Every example's pixel is marked (index y * w + x, row 0 at the bottom).
  for (const auto& e : r.examples)
    EXPECT_EQ(r.violation_mask[e["pixel"][1].get<int>() * 40 + e["pixel"][0].get<int>()], 1);
  // An exact order has an all-clear mask.
  std::vector<int32_t> exact(c.reversed.rbegin(), c.reversed.rend());
  EXPECT_EQ(ones(check_ordering(c.scene, c.cam, exact, o).violation_mask), 0);
}

TEST(ViolationMask, SupersampledPixelMarkedWhenAnySampleViolates) {
  const Case c = reversed_block(24);
  OracleOptions o;
  o.violation_mask = true;
  o.supersample = 3;
  const OracleResult r = check_ordering(c.scene, c.cam, c.reversed, o);
  ASSERT_EQ(r.violation_mask.size(), 24u * 24u);
  const int64_t marked = ones(r.violation_mask);
  // violating_pixels counts samples at S = 3: between one and nine per marked pixel.
  EXPECT_GT(marked, 0);
  EXPECT_LE(marked, r.violating_pixels);
  EXPECT_GE(marked * 9, r.violating_pixels);
}

TEST(ViolationMap, MarkedPixelsAreTheMask) {
  const Case c = reversed_block(48);
  OracleOptions o;
  o.violation_mask = true;
  const OracleResult r = check_ordering(c.scene, c.cam, c.reversed, o);
  const Image exact = render_exact(c.scene, c.cam);
  const Image map = violation_image(exact, r.violation_mask);
  EXPECT_EQ(marked_pixels(map), r.violating_pixels);
  EXPECT_EQ(marked_pixels(exact), 0);  // nothing in the exact image is pure red here
  EXPECT_THROW(violation_image(exact, std::vector<uint8_t>(7, 0)), std::exception);
}
