// `vobench run` and `reproduce` as a user sees them: [k/N] lines, --dry-run, unknown names
// refused before anything is made. No assertion on times.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/test_util.h"

namespace fs = std::filesystem;

namespace {
using Outcome = vob::test::CommandOutput;  // stdout and stderr together
Outcome vobench(const std::string& args) { return vob::test::run_vobench(VOB_BINARY, args); }

fs::path scratch(const std::string& name) { return vob::test::scratch_path("vobench_progress_cli", name); }

std::vector<std::string> lines_starting(const std::string& out, const std::string& prefix) {
  std::vector<std::string> v;
  size_t start = 0;
  while (start < out.size()) {
    const size_t end = out.find('\n', start);
    const std::string line = out.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (line.rfind(prefix, 0) == 0) v.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return v;
}

// 2 datasets x 2 orderers x 2 views x 1 size = 8 jobs.
const char* kSuite = R"({"name": "pc", "datasets": [{"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 3}},
    {"name": "helix", "set": {"cells": 2000}}], "algorithms": ["mpvo", "centroid"], "views": 2,
    "sizes": ["16x16"], "repeats": 1, "warmup": 0})";
}  // namespace

TEST(ProgressCli, RunCountsItsJobsAndTheDryRunListsThemWritingNothing) {
  const fs::path suite = scratch("pc.json"), results = scratch("pc.jsonl");
  std::ofstream(suite) << kSuite;
  fs::remove(results);
  fs::remove_all(scratch("images"));
  // The dry run: 8 job lines, exit 0, nothing written (no results file, no image folder).
  Outcome r = vobench("run " + suite.string() + " -o " + results.string() + " --dry-run");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(lines_starting(r.out, "    pc|").size(), 8u) << r.out;
  EXPECT_NE(r.out.find("run pc: 8 jobs (0 already done"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("uncalibrated"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(results));
  EXPECT_FALSE(fs::exists(scratch("images")));
  // The run: one [k/8] line per job, k = 1..8.
  r = vobench("run " + suite.string() + " -o " + results.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto lines = lines_starting(r.out, "[");
  ASSERT_EQ(lines.size(), 8u) << r.out;
  for (size_t i = 0; i < lines.size(); ++i)
    EXPECT_EQ(lines[i].rfind("[" + std::to_string(i + 1) + "/8] ", 0), 0u) << lines[i];
  EXPECT_NE(lines[0].find(" elapsed, ~"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find(" left: mpvo on gap(nx=2,ny=2,nz=3) view 0 16x16 t"), std::string::npos) << lines[0];
  // The dry run again: every job done, calibrated from the records, the file unchanged.
  const auto size = fs::file_size(results);
  r = vobench("run " + suite.string() + " -o " + results.string() + " --dry-run");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(lines_starting(r.out, "    pc|").size(), 8u) << r.out;
  EXPECT_NE(r.out.find("8 jobs (8 already done"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("calibrated from the frame times of 8 records"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[done: skipped]"), std::string::npos) << r.out;
  EXPECT_EQ(fs::file_size(results), size);
}

TEST(ProgressCli, DryRunOfAHugeSuiteMakesNoScene) {
  // 480 million cells: a dry run that made the scene would not finish.
  const fs::path suite = scratch("huge.json");
  std::ofstream(suite) << R"({"name": "huge", "datasets": [{"name": "gap", "set": {"nx": 1000, "ny": 1000, "nz": 80}}],
      "algorithms": ["mpvo", "xmpvo"], "views": 14, "sizes": ["512x512", "1024x1024"]})";
  const Outcome r = vobench("run " + suite.string() + " -o " + scratch("huge.jsonl").string() + " --dry-run");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(lines_starting(r.out, "    huge|").size(), 56u) << r.out;
  EXPECT_NE(r.out.find("dataset gap(nx=1000,ny=1000,nz=80): ~4.8e+08 cells (size from parameters)"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(scratch("huge.jsonl")));
}

TEST(ProgressCli, UnknownNamesExitTwoBeforeAnythingIsMade) {
  const fs::path suite = scratch("unknown.json");
  // A huge dataset first: validation must refuse the unknown orderer before making it.
  std::ofstream(suite) << R"({"name": "u", "datasets": [{"name": "gap", "set": {"nx": 1000, "ny": 1000, "nz": 80}}],
      "algorithms": ["mpvo", "xmpov"]})";
  Outcome r = vobench("run " + suite.string() + " -o " + scratch("u.jsonl").string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("unknown.json: algorithms[1]: 'xmpov' is not an orderer (did you mean 'xmpvo'? known: "),
            std::string::npos)
      << r.out;
  EXPECT_EQ(lines_starting(r.out, "").size(), 1u) << r.out;
  EXPECT_FALSE(fs::exists(scratch("u.jsonl")));
  r = vobench("run " + suite.string() + " -o " + scratch("u.jsonl").string() + " --dry-run");
  EXPECT_EQ(r.code, 2) << r.out;
  r = vobench("reproduce quik --dry-run");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("did you mean 'quick'?"), std::string::npos) << r.out;
  r = vobench("check --algorithm mpvo --dataset helx");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("did you mean 'helix'?"), std::string::npos) << r.out;
  r = vobench("check --algorithm mpvo --dataset gap --set nq=3");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("parameter nq: is not a known parameter (did you mean 'nx'?"), std::string::npos) << r.out;
}

TEST(ProgressCli, ReproduceDryRunListsEverySuiteAndWritesNothing) {
  const fs::path out = scratch("repro-out");
  fs::remove_all(out);
  const Outcome r = vobench("reproduce quick --tiny --dry-run -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("reproduction quick (tiny scale)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("quick: "), std::string::npos) << r.out;
  EXPECT_FALSE(lines_starting(r.out, "    quick/").empty()) << r.out;
  EXPECT_FALSE(fs::exists(out));
  // Every reproduction with a paper, a total each and one over all.
  const Outcome all = vobench("reproduce all --tiny --dry-run -o " + out.string());
  ASSERT_EQ(all.code, 0) << all.out;
  EXPECT_EQ(lines_starting(all.out, "all: ").size(), 1u) << all.out;
  EXPECT_GT(lines_starting(all.out, "reproduction ").size(), 5u) << all.out;
  EXPECT_FALSE(lines_starting(all.out, "xmpvo-scaling: ").empty()) << all.out;
  EXPECT_FALSE(fs::exists(out));
}
