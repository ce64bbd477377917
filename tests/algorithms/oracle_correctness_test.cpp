// The MPVO family checked by the z-buffer oracle (harness/oracle): exact on a convex
// acyclic block at pixel centres, and MPVO's blind spot across a gap made visible.
#include <gtest/gtest.h>

#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::testing;

namespace {

// Violating fragments of `spec` summed over the 14 Fibonacci views at 128 x 128.
int64_t violations_over_14_views(const std::string& spec, const Scene& scene, bool ortho) {
  auto orderer = make_orderer(spec);
  PhaseClock prep;
  const Scene own = scene.fresh();
  orderer->prepare(own, prep);
  ViewOptions opt;
  opt.width = opt.height = 128;
  opt.ortho = ortho;
  int64_t bad = 0;
  for (const Camera& view : fibonacci_views(scene.bounds(), 14, opt)) {
    PhaseClock clock;
    const Ordering o = orderer->order(view, clock);
    const OracleResult r = check_ordering(scene, view, o.order);
    EXPECT_GT(r.covered_pixels, 0);
    bad += r.violating_fragments;
  }
  return bad;
}

}  // namespace

TEST(OracleCorrectness, MpvoAndMpvoncAreExactOnAConvexBlock) {
  const Scene block = Scene::from_mesh("block", tet_block(5, 5, 5));
  for (const char* spec : {"mpvo", "mpvonc"})
    for (bool ortho : {false, true})
      EXPECT_EQ(violations_over_14_views(spec, block, ortho), 0)
          << spec << (ortho ? " orthographic" : " perspective");
}

TEST(OracleCorrectness, MpvoIsWrongAcrossAGapAndMpvoncFixesThisCase) {
  const Scene gap = Scene::from_mesh("two-blocks", two_blocks(3, 0.75));
  EXPECT_GT(violations_over_14_views("mpvo", gap, false), 0);
  EXPECT_EQ(violations_over_14_views("mpvonc", gap, false), 0);
}
