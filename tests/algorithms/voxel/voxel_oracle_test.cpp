// Voxel orderings under the splat oracle: distance-sort is exact; under perspective close-ups
// where splats overlap, ip-pbtf violates at fewer pixels than pbtf, and pbtf fewer than btf
// (Botha and Post): per view ip-pbtf <= pbtf (equal where no dividing plane crosses the
// material and the permutation is unchanged), and strictly over the view set.
#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"

namespace vob {
namespace {

Scene small(const std::string& name) {
  Params p(name);
  for (const char* k : {"nx", "ny", "nz"}) p.set(k, "24");
  return make_dataset(name, p);
}

struct Counts {
  int64_t v = 0;
};
Counts run(const std::string& spec, const Scene& s, const Camera& cam) {
  PreparedOrderer p = prepare_orderer(spec, s);
  PhaseClock clock;
  const Ordering o = p.orderer->order(cam, clock);
  Counts c;
  c.v = check_ordering(s, cam, o.order).violating_pixels;
  return c;
}

class VoxelRanking : public ::testing::TestWithParam<std::string> {};

TEST_P(VoxelRanking, IpPbtfBeatsPbtfBeatsBtfUnderPerspective) {
  const Scene s = small(GetParam());
  int64_t tb = 0, tp = 0, ti = 0;
  for (const Camera& cam : fibonacci_views(s.bounds(), 14, ViewOptions{128, 128, false, 2.0})) {
    const Counts b = run("btf", s, cam), p = run("pbtf", s, cam), i = run("ip-pbtf", s, cam);
    EXPECT_EQ(run("distance-sort", s, cam).v, 0);
    EXPECT_LE(i.v, p.v);
    tb += b.v, tp += p.v, ti += i.v;
  }
  EXPECT_LT(ti, tp);
  EXPECT_LT(tp, tb);
  RecordProperty("btf", std::to_string(tb));
  RecordProperty("pbtf", std::to_string(tp));
  RecordProperty("ip_pbtf", std::to_string(ti));
}

INSTANTIATE_TEST_SUITE_P(Volumes, VoxelRanking, ::testing::Values("block", "shells", "sparse"));

// Orthographic views: only the distance sort is exact for overlapping splats (grid orders
// keep face neighbours in depth order, voxel_order_test.cpp, but not farther pairs).
TEST(VoxelOracle, DistanceSortExactOrthographic) {
  const Scene s = small("shells");
  for (const Camera& cam : fibonacci_views(s.bounds(), 6, ViewOptions{128, 128, true, 1.0}))
    EXPECT_EQ(run("distance-sort", s, cam).v, 0);
}

}  // namespace
}  // namespace vob
