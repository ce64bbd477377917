// Every registered orderer on every hard case of its scene kind: it terminates, returns a
// complete permutation, and an orderer that detects cycles reports the cycle scenes'.
#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"

using namespace vob;

namespace {
struct Case {
  std::string orderer, dataset;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.orderer << " on " << c.dataset; }
std::vector<Case> all_cases() {
  std::vector<Case> out;
  for (const auto& d : dataset_registry())
    if (d.hard_case)
      for (const auto& o : orderer_registry())
        if (o.kind == d.kind) out.push_back({o.name, d.name});
  return out;
}
class HardCase : public ::testing::TestWithParam<Case> {};
}  // namespace

TEST_P(HardCase, TerminatesCompleteAndReportsCycles) {
  const Case c = GetParam();
  DatasetSpec spec;
  spec.name = c.dataset;
  const Scene scene = make_scene(spec);
  PreparedOrderer p = prepare_orderer(c.orderer, scene);
  const auto views = dataset_views(spec, scene, 3, {}, 128, 128, false, 1.0);
  ASSERT_FALSE(views.empty());
  int64_t cycles = 0;
  for (const auto& [vi, cam] : views) {
    FrameMeasurement m = measure_frame(p, cam, 0, 1);
    EXPECT_NO_THROW(check_complete(scene, m.ordering, c.orderer)) << "view " << vi;
    cycles += m.ordering.cycles.cycles;
    const OracleResult r = check_ordering(scene, cam, m.ordering.order);
    EXPECT_GE(r.covered_pixels, 0);
  }
  // The cycle scene's views look down the ring, where its face arrows form a cycle.
  if (c.dataset == "cycle" && p.orderer->claims().detects_cycles) EXPECT_GT(cycles, 0);
}

INSTANTIATE_TEST_SUITE_P(AllOrderers, HardCase, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           std::string s = i.param.orderer + "_on_" + i.param.dataset;
                           for (char& ch : s)
                             if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return s;
                         });

TEST(HardCases, TheRegistryHasTheIssuesHardCases) {
  for (const char* name : {"offset", "slivers", "edge-on", "eye-in-plane", "eye-inside", "cycle", "tiny"}) {
    bool found = false;
    for (const auto& d : dataset_registry()) found |= (d.name == name && d.hard_case);
    EXPECT_TRUE(found) << name;
  }
}
