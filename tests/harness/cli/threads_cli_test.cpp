// `--threads N` and a suite's "threads": [1, 0], end to end: the parallelism reaches the
// timed code (the threads-seen plugin reports it as counters), every record and the console
// say it, the generic report shows both counts side by side, a bad N is one line, exit 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/test_util.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
struct Outcome {
  int code;
  std::string out;  // stdout and stderr together
};

Outcome vobench(const std::string& args) {
  const vob::test::CommandOutput r = vob::test::run_command(std::string(VOB_BINARY) + " --plugin " +
                                                            VOB_THREADS_PLUGIN + " " + args + " 2>&1");
  return {r.code, r.out};
}

fs::path scratch(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("vobench_threads_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d / name;
}

fs::path suite_file(const std::string& name, const std::string& threads) {
  const fs::path p = scratch(name);
  std::ofstream(p) << R"({"name": "th", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
                          "algorithms": ["threads-seen", "mpvonc"], "views": 2, "sizes": ["16x16"],
                          "repeats": 1, "warmup": 0, "oracle": false, "threads": )"
                   << threads << "}";
  return p;
}

// The orderer records of a results file, and its context lines.
std::vector<json> records(const fs::path& results, std::vector<json>* contexts = nullptr) {
  std::vector<json> out;
  std::ifstream in(results);
  std::string line;
  while (std::getline(in, line)) {
    json j = json::parse(line);
    if (j.value("type", "") == "context") {
      if (contexts) contexts->push_back(j["context"]);
    } else if (j.value("type", "") != "plan") {
      out.push_back(j);
    }
  }
  return out;
}

// What `--threads 0` / a suite's 0 gives: all cores.
int all_cores() { return int(std::max(1u, std::thread::hardware_concurrency())); }
}  // namespace

TEST(CliThreads, ThreadsOneReachesRecordsKeysAndTheTimedCode) {
  const fs::path results = scratch("one.jsonl");
  fs::remove(results);
  // --threads replaces the suite's list: one count, 1.
  const Outcome r = vobench("run " + suite_file("one.json", "[1, 0]").string() + " -o " + results.string() +
                            " --threads 1");
  ASSERT_EQ(r.code, 0) << r.out;
  std::vector<json> contexts;
  const auto recs = records(results, &contexts);
  ASSERT_EQ(recs.size(), 4u);  // 2 orderers x 2 views, once
  ASSERT_EQ(contexts.size(), 1u);
  EXPECT_EQ(contexts[0]["threads"], 1);
  for (const json& j : recs) {
    EXPECT_EQ(j["threads"], 1) << j["key"];
    EXPECT_NE(j["key"].get<std::string>().find("|t1"), std::string::npos) << j["key"];
    if (j["algorithm"] == "threads-seen") {
      EXPECT_EQ(j["counters"]["run_threads"], 1);
      EXPECT_EQ(j["counters"]["loop_threads"], 1);  // no TBB worker joined the loop
    }
  }
  EXPECT_NE(r.out.find("threads-seen on gap(nx=3,ny=3,nz=4) view 0 16x16 t1:"), std::string::npos) << r.out;
  // check and order say the parallelism they ran with.
  const Outcome c = vobench("check -a mpvonc --dataset gap --set nx=3 --views 1 --size 16x16 --threads 1 --json");
  ASSERT_EQ(c.code, 0) << c.out;
  EXPECT_EQ(json::parse(c.out.substr(c.out.find('{')))["threads"], 1);
  const fs::path order = scratch("order.json");
  const Outcome o = vobench("order -a threads-seen --dataset gap --set nx=3 --view-index 0 --size 16x16 --threads 1 -o " +
                            order.string());
  ASSERT_EQ(o.code, 0) << o.out;
  std::ifstream in(order);
  const json oj = json::parse(in);
  EXPECT_EQ(oj["threads"], 1);
  EXPECT_EQ(oj["counters"]["run_threads"], 1);
}

TEST(CliThreads, ThreadListRunsEveryJobPerCountAndTheReportShowsBoth) {
  const fs::path results = scratch("list.jsonl");
  fs::remove(results);
  const fs::path suite = suite_file("list.json", "[1, 0]");
  const Outcome dry = vobench("run " + suite.string() + " -o " + results.string() + " --dry-run");
  ASSERT_EQ(dry.code, 0) << dry.out;
  const size_t counts = all_cores() > 1 ? 2 : 1;
  EXPECT_NE(dry.out.find(std::to_string(4 * counts) + " jobs"), std::string::npos) << dry.out;
  const Outcome r = vobench("run " + suite.string() + " -o " + results.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto recs = records(results);
  ASSERT_EQ(recs.size(), 4 * counts);
  std::set<int> seen;
  for (const json& j : recs) {
    seen.insert(j["threads"].get<int>());
    if (j["algorithm"] == "threads-seen") {
      EXPECT_EQ(j["counters"]["run_threads"], j["threads"]) << j["key"];
      EXPECT_LE(j["counters"]["loop_threads"].get<int>(), j["threads"].get<int>()) << j["key"];
    }
  }
  EXPECT_EQ(seen, (all_cores() > 1 ? std::set<int>{1, all_cores()} : std::set<int>{1}));
  // Run again: every key (thread count included) is there already.
  const Outcome again = vobench("run " + suite.string() + " -o " + results.string());
  EXPECT_NE(again.out.find("0 records written, " + std::to_string(4 * counts) + " already present"), std::string::npos)
      << again.out;
  const fs::path report = scratch("report");
  const Outcome rep = vobench("report " + results.string() + " -o " + report.string());
  ASSERT_EQ(rep.code, 0) << rep.out;
  std::ifstream in(report / "report.md");
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("| threads |"), std::string::npos) << md;
  if (all_cores() > 1) {
    const std::string both = "| threads-seen | 1 / " + std::to_string(all_cores()) + " |";
    EXPECT_NE(md.find("speed-up"), std::string::npos) << md;
    EXPECT_NE(md.find(both), std::string::npos) << md;
    EXPECT_NE(md.find("| mpvonc | 1 / " + std::to_string(all_cores()) + " |"), std::string::npos) << md;
  }
}

TEST(CliThreads, BadThreadsIsOneLineAndExitTwo) {
  const std::string scene = " --dataset gap --set nx=3 --views 1 --size 16x16";
  for (const std::string& cmd : {"check -a mpvonc" + scene, "order -a mpvonc --view-index 0 -o x.json" + scene,
                                 "run " + suite_file("bad.json", "1").string() + " -o " + scratch("bad.jsonl").string(),
                                 std::string("reproduce cook-table1 --dry-run")})
    for (const char* bad : {"-1", "abc", "1.5", "100000", ""}) {
      const Outcome r = vobench(cmd + " --threads '" + bad + "'");
      EXPECT_EQ(r.code, 2) << cmd << " --threads " << bad << ": " << r.out;
      EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
      EXPECT_NE(r.out.find("--threads"), std::string::npos) << r.out;
    }
}

// "interleave": the orderers of a dataset take turns frame by frame on each view (warm-up
// frames first), where a plain run measures one job after the other; the records say so and
// have their own keys, and a second run finds them done.
TEST(CliThreads, InterleaveTakesTurnsFrameByFrame) {
  const auto run = [&](bool interleave, const std::string& name, std::string& log) {
    const fs::path suite = scratch(name + ".json"), results = scratch(name + ".jsonl"), frames = scratch(name + ".log");
    fs::remove(results), fs::remove(frames);
    std::ofstream(suite) << R"({"name": "il", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
        "algorithms": ["frames-logged:tag=1", "frames-logged:tag=2"], "views": 2, "sizes": ["16x16"],
        "repeats": 2, "warmup": 1, "oracle": false, "threads": 1, "interleave": )"
                         << (interleave ? "true" : "false") << "}";
    const std::string env = "VOB_FRAME_LOG=" + frames.string() + " ";
    const vob::test::CommandOutput r = vob::test::run_command(env + VOB_BINARY + " --plugin " + VOB_THREADS_PLUGIN +
                                                              " run " + suite.string() + " -o " + results.string() + " 2>&1");
    EXPECT_EQ(r.code, 0) << r.out;
    std::ifstream in(frames);
    std::getline(in, log);
    const auto recs = records(results);
    EXPECT_EQ(recs.size(), 4u);
    for (const json& j : recs) {
      EXPECT_EQ(j.value("interleaved", false), interleave) << j["key"];
      EXPECT_EQ(j["key"].get<std::string>().find("|interleaved") != std::string::npos, interleave) << j["key"];
      EXPECT_EQ(j["total"]["samples"].size(), 2u) << j["key"];
    }
    const vob::test::CommandOutput again = vob::test::run_command(
        env + VOB_BINARY + " --plugin " + VOB_THREADS_PLUGIN + " run " + suite.string() + " -o " + results.string() + " 2>&1");
    EXPECT_EQ(again.code, 0) << again.out;
    EXPECT_NE(again.out.find("0 records written, 4 already present"), std::string::npos) << again.out;
    return recs;
  };
  std::string turns, plain;
  run(true, "interleaved", turns);
  run(false, "plain", plain);
  // Per view: a warm-up frame of each, then the two timed frames of each, in turns.
  EXPECT_EQ(turns, "1 2 1 2 1 2 1 2 1 2 1 2 ");
  // Per orderer: its views one after the other, warm-up and repeats together.
  EXPECT_EQ(plain, "1 1 1 1 1 1 2 2 2 2 2 2 ");
}
