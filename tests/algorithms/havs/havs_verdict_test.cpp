// HAVS has one verdict: what its k-buffer composites (Claims::composites), judged with the
// oracle's conventions. The check path (judge(), as `vobench check` calls it) and the record
// path (run_suite's record `oracle`) must agree, and the derived cell order's count is kept
// apart as oracle_cell_order.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "harness/bench/runner.h"
#include "harness/bench/verdict.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

namespace vob {
namespace {

Camera view_of(const Scene& s, int views, int i, int size) {
  ViewOptions o;
  o.width = o.height = size;
  return fibonacci_view(s.bounds(), views, i, o);
}

Verdict check_path(const std::string& spec, const Scene& scene, const Camera& cam, bool mask = true) {
  PreparedOrderer p = prepare_orderer(spec, scene);
  const FrameMeasurement m = measure_frame(p, cam, 0, 1);
  OracleOptions oo;
  oo.violation_mask = mask;
  return judge(*p.orderer, spec, scene, cam, m.ordering, oo, "--supersample");
}

TEST(HavsVerdict, DeclaresItComposites) {
  EXPECT_TRUE(make_orderer("havs")->claims().composites);
  EXPECT_FALSE(make_orderer("mpvo")->claims().composites);
}

TEST(HavsVerdict, LargeKOnAConvexMeshHasNoViolation) {
  const Scene scene = test::kuhn_block_scene(3);
  for (int v = 0; v < 6; ++v) {
    const Camera cam = view_of(scene, 6, v, 48);
    const Verdict verdict = check_path("havs:k=16", scene, cam);
    EXPECT_TRUE(verdict.composited);
    EXPECT_EQ(verdict.json().at("judged"), "composited");
    EXPECT_EQ(verdict.result.violating_pixels, 0) << "view " << v;
    EXPECT_EQ(verdict.result.violating_fragments, 0) << "view " << v;
    EXPECT_GT(verdict.result.covered_pixels, 0);
    EXPECT_EQ(verdict.result.samples, 48 * 48);
    EXPECT_FALSE(verdict.violated());
    ASSERT_TRUE(verdict.cell_order.has_value());
    EXPECT_EQ(verdict.cell_order_json().at("judged"), "derived cell order");
    EXPECT_TRUE(verdict.json().at("violating_pairs").is_null());
  }
}

TEST(HavsVerdict, OthersAreJudgedOnTheirOrder) {
  const Scene scene = test::kuhn_block_scene(3);
  const Verdict v = check_path("mpvo", scene, view_of(scene, 6, 1, 32));
  EXPECT_FALSE(v.composited);
  EXPECT_FALSE(v.cell_order.has_value());
  EXPECT_EQ(v.json().at("judged"), "order");
  EXPECT_TRUE(v.cell_order_json().is_null());
}

TEST(HavsVerdict, SupersampleIsRefused) {
  const Scene scene = test::kuhn_block_scene(2);
  const Camera cam = view_of(scene, 6, 0, 16);
  PreparedOrderer p = prepare_orderer("havs:k=4", scene);
  const FrameMeasurement m = measure_frame(p, cam, 0, 1);
  OracleOptions oo;
  oo.supersample = 2;
  const std::string msg =
      test::input_error([&] { judge(*p.orderer, "havs:k=4", scene, cam, m.ordering, oo, "--supersample"); });
  EXPECT_TRUE(test::contains(msg, "--supersample")) << msg;
  EXPECT_TRUE(test::contains(msg, "composites")) << msg;
}

// k = 1 on the 2000-cell helix violates; the record's oracle (run_suite) is the check
// path's verdict, count for count, and its mask marks exactly the violating pixels.
TEST(HavsVerdict, HelixK1SameCountInCheckAndRecord) {
  const Scene scene = test::dataset("helix", {{"cells", "2000"}});
  const int size = 64;
  const Camera cam = view_of(scene, 4, 1, size);
  const Verdict v = check_path("havs:k=1", scene, cam);
  EXPECT_GT(v.result.violating_pixels, 0);
  EXPECT_EQ(std::count(v.result.violation_mask.begin(), v.result.violation_mask.end(), uint8_t(1)),
            v.result.violating_pixels);
  // The analysis counters say the same.
  PreparedOrderer p = prepare_orderer("havs:k=1", scene);
  EXPECT_EQ(measure_frame(p, cam, 0, 1).ordering.counters.at("havs_violating_pixels"),
            double(v.result.violating_pixels));

  test::TempDir dir;
  const auto j = nlohmann::json::parse(R"({"name": "verdict", "datasets": [{"name": "helix",
      "set": {"cells": 2000}}], "algorithms": ["havs:k=1"], "sizes": ["64x64"], "views": 4,
      "view_indices": [1], "repeats": 1, "warmup": 0, "exterior_area": false, "image_views": [1]})");
  const SuiteSpec suite = SuiteSpec::from_json(j, "verdict.json");
  RunOptions opt;
  opt.results_path = dir.file("results.jsonl");
  run_suite(suite, opt);
  std::ifstream in(opt.results_path);
  std::string line;
  int records = 0;
  while (std::getline(in, line)) {
    const auto rec = nlohmann::json::parse(line);
    if (!rec.contains("algorithm")) continue;  // context lines
    ++records;
    EXPECT_EQ(rec.at("oracle").at("judged"), "composited");
    EXPECT_EQ(rec.at("oracle").at("violating_pixels").get<int64_t>(), v.result.violating_pixels);
    EXPECT_EQ(rec.at("oracle").at("violating_fragments").get<int64_t>(), v.result.violating_fragments);
    EXPECT_EQ(rec.at("oracle_cell_order").at("violating_pixels").get<int64_t>(),
              v.cell_order->violating_pixels);
    EXPECT_EQ(rec.at("claims").at("composites"), true);
    // Images relative to the results folder; the violation map marks the verdict's pixels.
    const std::string rel = rec.at("images").at("violations");
    EXPECT_EQ(rel.rfind("images/", 0), 0u) << rel;
    const Image map = read_png(dir.file(rel));
    EXPECT_EQ(marked_pixels(map), v.result.violating_pixels);
    for (const char* k : {"order", "exact", "diff"})
      EXPECT_TRUE(std::filesystem::exists(dir.file(rec.at("images").at(k)))) << k;
  }
  EXPECT_EQ(records, 1);
}

}  // namespace
}  // namespace vob
