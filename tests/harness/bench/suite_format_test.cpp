// The suite format of docs/pipeline.md: grids, labels, spread views, view directions,
// threads, probes, the tiny/full overlays, reproduction files, and the keys jobs get.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include <tbb/global_control.h>

#include "harness/bench/jobs.h"
#include "harness/bench/reproduction.h"
#include "harness/bench/scale_overlay.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"

using namespace vob;
using json = nlohmann::json;

namespace {
std::string error_of(const json& j) {
  try {
    SuiteSpec::from_json(j, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
json gap_suite() {
  return json::parse(R"({"name": "s", "datasets": [{"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 8},
      "grid": {"gaps": [0, 3]}, "label": "{gaps} gaps"}], "algorithms": ["mpvo"], "views": 6})");
}
}  // namespace

TEST(SuiteFormat, GridsExpandDatasetsAndAlgorithms) {
  auto j = gap_suite();
  j["algorithms"] = json::parse(R"(["mpvo", {"name": "centroid", "grid": {"key": ["view", "eye"]}}])");
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  ASSERT_EQ(s.datasets.size(), 2u);
  EXPECT_EQ(s.datasets[1].label(), "gap(gaps=3,nx=2,ny=2,nz=8)");
  EXPECT_EQ(s.datasets[1].row_label(), "3 gaps");
  EXPECT_EQ(s.algorithms, (std::vector<std::string>{"mpvo", "centroid:key=view", "centroid:key=eye"}));
}

TEST(SuiteFormat, RefusesBadGridsAndLabelsNamingTheEntry) {
  auto j = gap_suite();
  j["datasets"][0]["label"] = "same row";
  EXPECT_EQ(error_of(j).rfind("s.json: datasets[0].label: ", 0), 0u) << error_of(j);
  j = gap_suite();
  j["datasets"][0]["grid"]["gaps"] = json::array();
  EXPECT_EQ(error_of(j).rfind("s.json: datasets[0].grid.gaps: ", 0), 0u) << error_of(j);
  j = gap_suite();
  j["datasets"][0]["grid"]["gaps"] = {0, 99};  // 99 >= nz
  EXPECT_EQ(error_of(j).rfind("s.json: datasets[0].grid: ", 0), 0u) << error_of(j);
  j = gap_suite();
  j["algorithms"] = json::parse(R"([{"name": "havs", "grid": {"k": [2, 99]}}])");
  EXPECT_EQ(error_of(j).rfind("s.json: algorithms[0]: ", 0), 0u) << error_of(j);
}

TEST(SuiteFormat, SpreadViewsDirectionsAndThreads) {
  auto j = gap_suite();
  j["views"] = 14;
  j["spread_views"] = 3;
  j["threads"] = 1;
  SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  EXPECT_EQ(s.view_indices, (std::vector<int>{0, 4, 9}));
  EXPECT_EQ(s.threads, std::vector<int>{1});
  j["view_indices"] = {1};
  EXPECT_EQ(error_of(j).rfind("s.json: view_indices: ", 0), 0u) << error_of(j);
  j = gap_suite();
  j.erase("views");
  j["view_directions"] = json::parse(R"([{"from": [1, 0, 0], "up": [0, 0, 1]}, {"from": [0, 1, 0]}])");
  s = SuiteSpec::from_json(j, "s.json");
  EXPECT_EQ(s.views, 2);
  j["view_directions"][1]["up"] = {0, 2, 0};  // parallel to from
  EXPECT_EQ(error_of(j).rfind("s.json: view_directions[1].up: ", 0), 0u) << error_of(j);
}

TEST(SuiteFormat, ProbesAreCheckedByADryRun) {
  auto j = gap_suite();
  j["probes"] = json::parse(R"([{"name": "xmpvo-stability"}])");
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  ASSERT_EQ(s.probes.size(), 1u);
  EXPECT_EQ(s.probes[0].datasets.size(), 2u);  // needs a scene: the suite's datasets
  EXPECT_EQ(s.probes[0].label(), "probe:xmpvo-stability");
  j["probes"][0]["set"] = {{"colour", 1}};
  EXPECT_EQ(error_of(j).rfind("s.json: probes[0].set: ", 0), 0u) << error_of(j);
  j["probes"][0] = {{"name", "nope"}};
  EXPECT_EQ(error_of(j).rfind("s.json: probes[0].name: ", 0), 0u) << error_of(j);
  j = json::parse(R"({"name": "p", "probes": [{"name": "xmpvo-stability"}]})");
  EXPECT_EQ(error_of(j).rfind("s.json: probes[0]: ", 0), 0u) << error_of(j);  // no datasets anywhere
}

TEST(SuiteFormat, OverlaysReplaceKeysRecursivelyAtTheirScale) {
  const json j = json::parse(R"({"views": 14, "datasets": [{"name": "gap", "set": {"nx": 10, "ny": 10},
      "tiny": {"set": {"nx": 2}}}], "tiny": {"views": 2}, "full": {"views": 50}})");
  const json tiny = apply_scale(j, "tiny", "r.json");
  EXPECT_EQ(tiny["views"], 2);
  EXPECT_EQ(tiny["datasets"][0]["set"], json::parse(R"({"nx": 2, "ny": 10})"));
  EXPECT_FALSE(tiny.contains("tiny") || tiny.contains("full") || tiny["datasets"][0].contains("tiny"));
  EXPECT_EQ(apply_scale(j, "full", "r.json")["views"], 50);
  EXPECT_EQ(apply_scale(j, "default", "r.json")["datasets"][0]["set"]["nx"], 10);
  EXPECT_THROW(apply_scale(json::parse(R"({"tiny": 3})"), "tiny", "r.json"), InputError);
}

TEST(SuiteFormat, KeysCarryReproductionViewSetAndScale) {
  const SuiteSpec s = SuiteSpec::from_json(gap_suite(), "s.json");
  const auto plans = plan_datasets(s);
  ASSERT_EQ(plans.size(), 2u);
  const Scene scene = make_scene(plans[0].dataset);
  const RunTags tags{"repro", "paper", "tiny"};
  const auto jobs = dataset_jobs(s, plans[0], scene, tags);
  ASSERT_EQ(jobs.size(), 6u);  // mpvo x 6 views
  const std::string t = "|t" + std::to_string(run_threads());  // the parallelism in effect
  EXPECT_EQ(jobs[2].key, "repro/s|mpvo|gap(gaps=0,nx=2,ny=2,nz=8)|v2/6|512x512|r3w1|oracle|ss1" + t + "|tiny");
  EXPECT_EQ(dataset_jobs(s, plans[0], scene, RunTags{})[2].key,
            "s|mpvo|gap(gaps=0,nx=2,ny=2,nz=8)|v2/6|512x512|r3w1|oracle|ss1" + t);
}

TEST(SuiteFormat, KeysChangeWithEverySettingThatChangesARecord) {
  const SuiteSpec base = SuiteSpec::from_json(gap_suite(), "s.json");
  const auto plans = plan_datasets(base);
  const Scene scene = make_scene(plans[0].dataset);
  const std::string k0 = dataset_jobs(base, plans[0], scene, RunTags{})[0].key;
  for (const auto& [field, value] : std::vector<std::pair<std::string, json>>{
           {"repeats", 5}, {"warmup", 0}, {"oracle", false}, {"supersample", 2}, {"image_error", true},
           {"threads", 1}}) {
    auto j = gap_suite();
    j[field] = value;
    const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
    EXPECT_NE(dataset_jobs(s, plans[0], scene, RunTags{})[0].key, k0) << field;
  }
}

// "threads": [1, 0]: every job once per thread count, keyed by the count in effect
// (0: all cores); one key per effective count, whatever the machine.
TEST(SuiteFormat, ThreadListExpandsEveryJobPerThreadCount) {
  auto j = gap_suite();
  j["threads"] = json::array({1, 0});
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  EXPECT_EQ(s.threads, (std::vector<int>{1, 0}));
  const auto plans = plan_datasets(s);
  const Scene scene = make_scene(plans[0].dataset);
  const auto jobs = dataset_jobs(s, plans[0], scene, RunTags{});
  const int all = effective_threads(0);
  ASSERT_EQ(jobs.size(), all > 1 ? 12u : 6u);  // mpvo x 6 views x thread counts
  EXPECT_EQ(jobs[0].threads, 1);
  EXPECT_NE(jobs[0].key.find("|ss1|t1"), std::string::npos) << jobs[0].key;
  if (all > 1) {
    EXPECT_EQ(jobs[6].threads, 0);
    EXPECT_EQ(jobs[6].view_index, 0);
    EXPECT_NE(jobs[6].key.find("|ss1|t" + std::to_string(all)), std::string::npos) << jobs[6].key;
  }
  // Under an outer limit (--threads 1 would also replace the list), both counts are 1: one job each.
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(dataset_jobs(s, plans[0], scene, RunTags{}).size(), 6u);
  }
  for (const char* bad : {"[]", "[1, 1]", "[-1]", "[2000]", "\"2\"", "[1.5]"}) {
    j["threads"] = json::parse(bad);
    EXPECT_EQ(error_of(j).rfind("s.json: threads", 0), 0u) << bad << ": " << error_of(j);
  }
}

TEST(SuiteFormat, OrbitViewsAreOrbitFramesWithTheirOwnKeys) {
  auto j = gap_suite();
  j["views"] = 30;
  j["orbit"] = true;
  j["spread_views"] = 3;
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  const auto plans = plan_datasets(s);
  const Scene scene = make_scene(plans[0].dataset);
  const auto views = suite_views(s, plans[0].dataset, scene, 64, 32);
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[1].first, 10);
  const Camera want = orbit_view(scene.bounds(), 30, 10, ViewOptions{64, 32});
  EXPECT_EQ(views[1].second.to_json(), want.to_json());
  EXPECT_NE(views[1].second.to_json(), fibonacci_view(scene.bounds(), 30, 10, ViewOptions{64, 32}).to_json());
  EXPECT_EQ(dataset_jobs(s, plans[0], scene, RunTags{})[1].key,
            "s|mpvo|gap(gaps=0,nx=2,ny=2,nz=8)|o10/30|512x512|r3w1|oracle|ss1|t" + std::to_string(run_threads()));
  j.erase("views");
  j.erase("spread_views");
  j["view_directions"] = json::parse(R"([{"from": [1, 0, 0]}])");
  EXPECT_EQ(error_of(j).rfind("s.json: orbit: ", 0), 0u) << error_of(j);
}

TEST(Reproduction, FindsFilesByNameAndReadsSuitesAtTheScale) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("vob_repro_" + std::to_string(getpid()));
  fs::create_directories(dir / "paper");
  std::ofstream(dir / "plain.json") << gap_suite().dump();
  json r = {{"reproduction", "r1"}, {"paper", nullptr}, {"summary", "one"},
            {"suites", json::array({"plain.json", gap_suite()})}};
  r["suites"][1]["name"] = "s2";
  r["suites"][1]["tiny"] = {{"views", 2}};
  std::ofstream(dir / "paper" / "r1.json") << r.dump();
  EXPECT_EQ(find_reproduction(dir.string(), "r1"), (dir / "paper" / "r1.json").string());
  EXPECT_EQ(find_reproduction(dir.string(), "plain"), "");
  const Reproduction rep = load_reproduction(find_reproduction(dir.string(), "r1"), "tiny", dir.string());
  ASSERT_EQ(rep.suites.size(), 2u);
  EXPECT_EQ(rep.suites[1].views, 2);
  EXPECT_EQ(rep.suites[0].views, 6);
  EXPECT_TRUE(rep.paper.empty());
  r["suites"][1]["name"] = "s";  // two suites named s
  std::ofstream(dir / "paper" / "r1.json") << r.dump();
  EXPECT_THROW(load_reproduction((dir / "paper" / "r1.json").string(), "default", dir.string()), InputError);
  std::ofstream(dir / "paper" / "r2.json") << r.dump();  // the same name twice
  EXPECT_THROW(list_reproductions(dir.string()), InputError);
  fs::remove_all(dir);
}
