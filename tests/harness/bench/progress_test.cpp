// [k/N] progress, the job plan behind --dry-run, and unknown names refused with the known
// ones (docs/pipeline.md "Progress and --dry-run"). No assertion on times.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "harness/bench/job_plan.h"
#include "harness/bench/names.h"
#include "harness/bench/progress.h"
#include "harness/bench/resources.h"
#include "harness/bench/runner.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"

using namespace vob;
namespace fs = std::filesystem;

namespace {
SuiteSpec suite_of(const std::string& text) { return SuiteSpec::from_json(nlohmann::json::parse(text), "p.json"); }

std::string error_of(const std::string& text) {
  try {
    suite_of(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("vobench_progress_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d / name;
}

// Runs the suite into `results`, returning the record lines ([k/N] ...).
std::vector<std::string> run_lines(const SuiteSpec& s, const fs::path& results) {
  std::vector<std::string> lines;
  RunOptions opt;
  opt.results_path = results.string();
  opt.progress = [&](const std::string& l) {
    if (l.rfind("[", 0) == 0) lines.push_back(l);
  };
  run_suite(s, opt);
  return lines;
}

const char* kSmall = R"({"name": "p", "datasets": [{"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 3}},
    {"name": "eye-inside", "set": {"n": 2}}], "algorithms": ["mpvo", "centroid"], "views": 3,
    "sizes": ["16x16", "8x8"], "repeats": 1, "warmup": 0})";
}  // namespace

TEST(JobPlan, CountsTheJobsOfTheRunWithoutMakingScenes) {
  const SuiteSpec s = suite_of(kSmall);
  const RunPlan plan = plan_run(s, RunTags{}, KnownRecords{});
  ASSERT_EQ(plan.datasets.size(), 2u);
  // gap: 2 orderers x 2 sizes x 3 views; eye-inside: its own 2 cameras.
  EXPECT_EQ(plan.datasets[0].jobs.size(), 12u);
  EXPECT_EQ(plan.datasets[1].jobs.size(), 8u);
  EXPECT_EQ(plan.datasets[1].views_note, "views: the dataset's own cameras");
  EXPECT_EQ(plan.jobs(), 20u);
  EXPECT_EQ(plan.to_do(), 20u);
  EXPECT_GT(plan.cost_to_do(), 0);
  EXPECT_EQ(plan.datasets[0].size_from, "parameters");
  EXPECT_DOUBLE_EQ(plan.datasets[0].primitives, 72);  // 6 tets per hex
}

TEST(JobPlan, KeysAreTheRunsKeys) {
  const SuiteSpec s = suite_of(kSmall);
  const RunPlan plan = plan_run(s, RunTags{"r", "paper", "tiny"}, KnownRecords{});
  const auto plans = plan_datasets(s);
  for (size_t i = 0; i < plans.size(); ++i) {
    const Scene scene = make_scene(plans[i].dataset);
    const auto jobs = dataset_jobs(s, plans[i], scene, RunTags{"r", "paper", "tiny"});
    ASSERT_EQ(jobs.size(), plan.datasets[i].jobs.size());
    for (size_t j = 0; j < jobs.size(); ++j) EXPECT_EQ(jobs[j].key, plan.datasets[i].jobs[j].key);
  }
}

TEST(JobPlan, ProbesAndViewChoicesCount) {
  SuiteSpec s = suite_of(R"({"name": "q", "datasets": [{"name": "helix", "set": {"cells": 2000}}],
      "algorithms": ["mpvo"], "views": 14, "spread_views": 4, "sizes": ["8x8"],
      "probes": [{"name": "havs-sorts", "set": {"n": 1000}, "grid": {"sort": ["shell", "heap"]}}]})");
  RunPlan plan = plan_run(s, RunTags{}, KnownRecords{});
  EXPECT_EQ(plan.jobs(), 4u + 2u);  // 4 views; two probe units without a scene
  EXPECT_EQ(plan.datasets.back().label, "");
  EXPECT_DOUBLE_EQ(plan.datasets[0].primitives, 2000);
  s = suite_of(R"({"name": "q", "datasets": [{"name": "sphere"}], "algorithms": ["triangle-centroid"],
      "view_directions": [{"from": [1, 0, 0]}, {"from": [0, 1, 0]}, {"from": [0, 0, 1], "up": [0, 1, 0]}]})");
  EXPECT_EQ(plan_run(s, RunTags{}, KnownRecords{}).jobs(), 3u);
  s = suite_of(R"({"name": "q", "datasets": [{"name": "sphere"}], "algorithms": ["triangle-centroid"],
      "orbit": true, "views": 8, "view_indices": [1, 2]})");
  EXPECT_EQ(plan_run(s, RunTags{}, KnownRecords{}).jobs(), 2u);
}

TEST(JobPlan, CostGrowsWithPrimitivesPixelsAndFrames) {
  const double base = orderer_job_cost(1e5, 512 * 512, 3, 1, 1);
  EXPECT_GT(orderer_job_cost(1e6, 512 * 512, 3, 1, 1), base);
  EXPECT_GT(orderer_job_cost(1e5, 1024 * 1024, 3, 1, 1), base);
  EXPECT_GT(orderer_job_cost(1e5, 512 * 512, 9, 1, 1), base);
  EXPECT_GT(base, orderer_job_cost(1e5, 512 * 512, 3, 1, 0));  // the oracle is work too
  std::string from;
  DatasetSpec gap;
  gap.name = "gap";
  EXPECT_DOUBLE_EQ(estimated_primitives(gap, &from), 1.5e6);  // the defaults
  EXPECT_EQ(from, "parameters");
}

TEST(Progress, CountsEveryJobAndSkippedOnesAsDone) {
  const SuiteSpec s = suite_of(kSmall);
  const fs::path results = scratch("count.jsonl");
  fs::remove(results);
  auto lines = run_lines(s, results);
  ASSERT_EQ(lines.size(), 20u);
  for (size_t i = 0; i < lines.size(); ++i)
    EXPECT_EQ(lines[i].rfind("[" + std::to_string(i + 1) + "/20] ", 0), 0u) << lines[i];
  EXPECT_TRUE(std::regex_search(lines[0], std::regex(R"(^\[1/20\] \d\d:\d\d elapsed, ~\d\d:\d\d left: mpvo on gap)")))
      << lines[0];
  EXPECT_NE(lines.back().find(" ms/frame"), std::string::npos) << lines.back();
  // A third orderer: the 20 finished jobs are skipped but counted, so the new ones are 21..30.
  auto j = nlohmann::json::parse(kSmall);
  j["algorithms"].push_back("vtk-centroid");
  lines = run_lines(SuiteSpec::from_json(j, "p.json"), results);
  ASSERT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines.front().rfind("[", 0), 0u);
  EXPECT_NE(lines.front().find("/30] "), std::string::npos) << lines.front();
  EXPECT_EQ(lines.back().rfind("[30/30] ", 0), 0u) << lines.back();
  // The records calibrate the next estimate and say what is done.
  const KnownRecords known = KnownRecords::read(results.string());
  EXPECT_EQ(known.keys.size(), 30u);
  EXPECT_EQ(known.timed, 30u);
  EXPECT_GT(known.seconds_per_unit(), 0);
  EXPECT_EQ(plan_run(SuiteSpec::from_json(j, "p.json"), RunTags{}, known).to_do(), 0u);
  // Both runs were this build's.
  EXPECT_TRUE(done_by_other_revisions(plan_run(SuiteSpec::from_json(j, "p.json"), RunTags{}, known), known,
                                      source_revision())
                  .empty());
}

TEST(JobPlan, DoneJobsOfOtherBuildsAreCountedByRevision) {
  // Records name their run; the run's context line names the source revision.
  const fs::path results = scratch("revisions.jsonl");
  {
    std::ofstream out(results);
    out << R"({"key": "context|r1", "type": "context", "run_id": "r1", "context": {"git_sha": "aaa1111"}})" << "\n"
        << R"({"key": "k1", "run_id": "r1"})" << "\n"
        << R"({"key": "k2", "run_id": "r1"})" << "\n"
        << R"({"key": "context|r2", "type": "context", "run_id": "r2", "context": {"git_sha": "bbb2222"}})" << "\n"
        << R"({"key": "k3", "run_id": "r2"})" << "\n"
        << R"({"key": "k4", "run_id": "gone"})" << "\n";
  }
  const KnownRecords known = KnownRecords::read(results.string());
  EXPECT_EQ(known.revision.at("k1"), "aaa1111");
  EXPECT_EQ(known.revision.at("k3"), "bbb2222");
  EXPECT_EQ(known.revision.at("k4"), "");
  EXPECT_EQ(known.revision.count("context|r1"), 0u);
  RunPlan plan;
  plan.datasets.resize(1);
  for (const char* key : {"k1", "k2", "k3", "k4", "k5"}) {
    PlannedJob j;
    j.key = key;
    j.done = known.keys.count(key) > 0;
    plan.datasets[0].jobs.push_back(j);
  }
  auto others = done_by_other_revisions(plan, known, "bbb2222");
  EXPECT_EQ(others.size(), 2u);
  EXPECT_EQ(others["aaa1111"], 2u);
  EXPECT_EQ(others["unknown"], 1u);  // a record whose run has no context line
  EXPECT_TRUE(done_by_other_revisions(plan, known, "bbb2222", [](const PlannedDataset&, const PlannedJob& j) {
                return j.key == "k3";
              }).empty());
  const std::string note = other_revisions_note(others, "bbb2222", "--force");
  EXPECT_NE(note.find("3 of the jobs done"), std::string::npos) << note;
  EXPECT_NE(note.find("2 by aaa1111"), std::string::npos) << note;
  EXPECT_NE(note.find("--force"), std::string::npos) << note;
  EXPECT_EQ(other_revisions_note({}, "bbb2222", "--force"), "");
}

TEST(Progress, StatusAndClock) {
  EXPECT_EQ(ProgressTracker::clock_text(41), "00:41");
  EXPECT_EQ(ProgressTracker::clock_text(190), "03:10");
  EXPECT_EQ(ProgressTracker::clock_text(3723), "1:02:03");
  ProgressTracker all;
  all.add(10, 100);
  ProgressTracker one(&all);
  one.add(4, 40);
  EXPECT_NE(one.status().find("time left unknown"), std::string::npos) << one.status();
  one.skipped();
  one.finished(10);
  EXPECT_EQ(one.status().rfind("[2/4] ", 0), 0u) << one.status();
  EXPECT_NE(one.status().find("(all: [2/10]"), std::string::npos) << one.status();
  one.replace(2, 30, 3, 30);  // a dataset with one more job than planned
  EXPECT_EQ(one.total(), 5u);
  EXPECT_EQ(all.total(), 11u);
}

TEST(Names, ClosestAndKnown) {
  const std::vector<std::string> known = {"gap", "helix", "zoo", "sphere", "spheres"};
  EXPECT_EQ(closest_name("helx", known), "helix");
  EXPECT_EQ(closest_name("Sphere", known), "sphere");
  EXPECT_EQ(closest_name("qqqqqq", known), "");
  EXPECT_EQ(known_names_hint("hel", known).rfind("did you mean 'helix'? known: gap, helix", 0), 0u);
}

// Every unknown name is refused by suite validation, naming the file, the entry and the
// name, with the known names; nothing is generated (the datasets are huge).
TEST(Names, UnknownNamesInSuitesNameFileEntryAndKnownOnes) {
  const std::string big = R"({"name": "gap", "set": {"nx": 1000, "ny": 1000, "nz": 80}})";
  const auto suite = [&](const std::string& datasets, const std::string& rest) {
    return R"({"name": "u", "datasets": [)" + big + (datasets.empty() ? "" : ", " + datasets) + "], " + rest + "}";
  };
  struct Case {
    std::string text, start, has;
  };
  for (const Case& c : std::vector<Case>{
           {suite("", R"("algorithms": ["mpov"])"), "p.json: algorithms[0]: ", "did you mean 'mpvo'?"},
           {suite(R"({"name": "helx"})", R"("algorithms": ["mpvo"])"), "p.json: datasets[1].name: ", "'helix'"},
           {suite(R"({"name": "helix", "set": {"cels": 5}})", R"("algorithms": ["mpvo"])"),
            "p.json: datasets[1].set: helix: parameter cels", "did you mean 'cells'?"},
           {suite("", R"("algorithms": [{"name": "havs", "set": {"kk": 2}}])"), "p.json: algorithms[0]: ",
            "parameter kk"},
           {suite("", R"("algorithms": ["mpvo"], "probes": [{"name": "havs-sort"}])"), "p.json: probes[0].name: ",
            "did you mean 'havs-sorts'?"},
           {suite("", R"("algorithms": ["mpvo"], "probes": [{"name": "havs-sorts", "set": {"sorts": "heap"}}])"),
            "p.json: probes[0].set: ", "did you mean 'sort'?"},
           {suite("", R"("algorithms": ["btf"])"), "p.json: algorithms[0]: ", "no dataset of this suite is voxels"},
           {suite("", R"("algorithms": ["mpvo"], "sizes": ["512x"])"), "p.json: sizes[0]", "WxH"}}) {
    const std::string e = error_of(c.text);
    EXPECT_EQ(e.rfind(c.start, 0), 0u) << e;
    EXPECT_NE(e.find(c.has), std::string::npos) << e;
  }
}
