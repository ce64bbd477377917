// Volumes touching face to face with duplicated interface nodes (the touching-* hard cases):
// every orderer that claims object exactness gives zero oracle violations at 4 x 4 samples
// per pixel over 14 views, perspective and orthographic, with no cycle and no undecided
// face pair. Before coincident exterior faces were ordered (face_pairs.h, coplanar_order)
// xmpvo failed up to 6 and bsp-xmpvo 7 to 13 of the 14 views per case (512x512, S = 4; at
// this test's 96x96 on touching-rotated 5 and 13); MPVO, which has no relation between
// the blocks, fails some, which shows the cases need the exterior relations.
#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using vob::testing::is_permutation_of;

namespace {

std::vector<std::string> touching_cases() {
  std::vector<std::string> out;
  for (const auto& d : dataset_registry())
    if (d.hard_case && d.name.rfind("touching-", 0) == 0) out.push_back(d.name);
  return out;
}

std::vector<std::string> object_exact_cell_orderers() {
  std::vector<std::string> out;
  for (const auto& info : orderer_registry())
    if (info.kind == SceneKind::Cells && make_orderer(info.name)->claims().object_exact)
      out.push_back(info.name);
  return out;
}

// Views of the 14-view set where `orderer` violates at S = `supersample`.
int failing_views(const std::string& orderer, const Scene& s, bool ortho, int supersample,
                  bool expect_exact) {
  auto o = make_orderer(orderer);
  PhaseClock prep;
  const Scene scene = s.fresh();
  o->prepare(scene, prep);
  OracleOptions opt;
  opt.supersample = supersample;
  int failures = 0;
  for (int v = 0; v < 14; ++v) {
    ViewOptions vo{96, 96};
    vo.ortho = ortho;
    const Camera view = fibonacci_view(s.bounds(), 14, v, vo);
    PhaseClock clock;
    const Ordering r = o->order(view, clock);
    EXPECT_TRUE(is_permutation_of(r.order, s.mesh().num_cells()));
    const OracleResult res = check_ordering(s, view, r.order, opt);
    failures += !res.ok();
    if (!expect_exact) continue;
    const std::string where = orderer + " on " + s.name() + (ortho ? " ortho" : "") + " view " + std::to_string(v);
    EXPECT_EQ(res.violating_fragments, 0) << where << ": " << res.to_json().dump();
    EXPECT_EQ(r.cycles.cycles, 0) << where;
    EXPECT_EQ(r.counters.at("depth_undecided"), 0) << where;
  }
  return failures;
}

}  // namespace

TEST(TouchingVolumes, TheRegistryHasTheCases) {
  const auto cases = touching_cases();
  for (const char* name : {"touching-conforming", "touching-shifted", "touching-rotated",
                           "touching-overhang", "touching-edge", "touching-hex"})
    EXPECT_NE(std::find(cases.begin(), cases.end(), name), cases.end()) << name;
  const auto exact = object_exact_cell_orderers();
  for (const char* name : {"xmpvo", "bsp-xmpvo"})
    EXPECT_NE(std::find(exact.begin(), exact.end(), name), exact.end()) << name;
}

TEST(TouchingVolumes, ObjectExactOrderersAreExactAtSupersampling) {
  for (const std::string& name : touching_cases()) {
    const Scene s = make_dataset(name, Params(name));
    for (const std::string& orderer : object_exact_cell_orderers())
      for (bool ortho : {false, true}) failing_views(orderer, s, ortho, 4, true);
  }
}

TEST(TouchingVolumes, MpvoAloneFailsThem) {
  int failures = 0;
  for (const std::string& name : touching_cases())
    failures += failing_views("mpvo", make_dataset(name, Params(name)), false, 1, false);
  EXPECT_GT(failures, 0);
}
