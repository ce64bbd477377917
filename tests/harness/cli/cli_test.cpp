// Runs the vobench binary as a user would and checks exit codes, messages and outputs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/test_util.h"

namespace fs = std::filesystem;

namespace {
using Outcome = vob::test::CommandOutput;  // stdout and stderr together
Outcome vobench(const std::string& args) { return vob::test::run_vobench(VOB_BINARY, args); }

fs::path scratch(const std::string& name) { return vob::test::scratch_path("vobench_cli", name); }

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

const char* kSmallGap = "--dataset gap --set nx=4 --set ny=4 --set nz=6";

// `vobench order ARGS -o FILE` (FILE in the scratch folder): the JSON written, or null (and
// a failure) when the command did not exit 0.
nlohmann::json order_json(const std::string& args, const std::string& file) {
  const fs::path out = scratch(file);
  const Outcome r = vobench("order " + args + " -o " + out.string());
  EXPECT_EQ(r.code, 0) << r.out;
  if (r.code != 0) return nullptr;
  std::ifstream in(out);
  return nlohmann::json::parse(in);
}
}  // namespace

TEST(Cli, ListNamesTheFirstOrderersAndDatasets) {
  const Outcome r = vobench("list");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* name : {"mpvo", "mpvonc", "centroid", "vtk-centroid", "gap", "helix", "zoo"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
}

// The listing comes from the declared ParamSpecs: text and JSON say the same defaults and ranges.
TEST(Cli, ListJsonHasEveryOrdererWithClaimsAndDeclaredParameters) {
  const Outcome r = vobench("list --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.at("orderers").is_array());
  bool saw_havs = false;
  for (const auto& o : j.at("orderers")) {
    for (const char* k : {"name", "kind", "summary", "claims", "params"}) EXPECT_TRUE(o.contains(k)) << k;
    for (const auto& p : o.at("params"))
      for (const char* k : {"name", "kind", "default", "doc"}) EXPECT_TRUE(p.contains(k)) << o["name"] << " " << k;
    if (o.at("name") == "havs") {
      saw_havs = true;
      const auto& k = o.at("params").at(0);
      EXPECT_EQ(k.at("name"), "k");
      EXPECT_EQ(k.at("kind"), "int");
      EXPECT_EQ(k.at("default"), 2);
      EXPECT_EQ(k.at("range"), nlohmann::json::array({1, 16}));
    }
    if (o.at("name") == "xmpvo") {
      EXPECT_EQ(o.at("claims").at("object_exact"), true);
    }
  }
  EXPECT_TRUE(saw_havs);
  EXPECT_FALSE(j.at("datasets").empty());
  EXPECT_FALSE(j.at("reproductions").empty());
  const Outcome text = vobench("list");
  EXPECT_NE(text.out.find("k=2 (1..16): k-buffer entries per pixel"), std::string::npos) << text.out;
}

// The record's "parameters" lists every declared parameter with its effective value.
TEST(Cli, OrderJsonParametersAreTheResolvedSpec) {
  const nlohmann::json j = order_json(std::string("--algorithm vtk-centroid:chunk=7 ") + kSmallGap +
                                          " --views 4 --view-index 1 --size 32x32", "order_params.json");
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("parameters"), (nlohmann::json{{"chunk", 7}}));
}

TEST(Cli, CheckPassesExactOrderAndExitsZero) {
  const Outcome r = vobench(std::string("check --algorithm mpvo ") + kSmallGap + " --views 4 --size 64x64");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("0 of 4 views with violations"), std::string::npos) << r.out;
}

TEST(Cli, CheckJsonHasTheOracleKeysPerView) {
  const Outcome r = vobench(std::string("check --algorithm centroid ") + kSmallGap +
                        " --views 2 --size 48x40 --json");
  ASSERT_LE(r.code, 1) << r.out;
  const auto j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
  ASSERT_EQ(j["views"].size(), 2u);
  for (const char* k : {"covered_pixels", "violating_pixels", "violating_fragments", "violating_pairs", "max_k"})
    EXPECT_TRUE(j["views"][0].contains(k)) << k;
  EXPECT_EQ(j["views"][0]["camera"]["width"], 48);
  EXPECT_EQ(j["views"][0]["camera"]["height"], 40);
}

TEST(Cli, CheckExitsOneOnAViolation) {
  // MPVO cannot see across gaps: some of 14 views of a gapped block must fail.
  const Outcome r = vobench("check --algorithm mpvo --dataset gap --set nx=4 --set ny=4 --set nz=12 "
                        "--set gaps=3 --views 14 --size 96x96");
  EXPECT_EQ(r.code, 1) << r.out;
}

TEST(Cli, OrderWritesAVerifiableOrderJson) {
  const nlohmann::json j = order_json(std::string("--algorithm mpvonc ") + kSmallGap +
                                          " --eye 9,1,2 --target 0,0,0 --up 0,0,1 --fov 35 --size 80x60",
                                      "order.json");
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["primitive_kind"], "cells");
  EXPECT_EQ(j["order"].size(), j["primitives"].get<size_t>());
  EXPECT_EQ(j["camera"]["fov"], 35.0);
  EXPECT_EQ(j["camera"]["width"], 80);
  EXPECT_TRUE(j.contains("prepare_phases"));
  EXPECT_TRUE(j["phases"].contains("I create partial order"));
  EXPECT_TRUE(j.contains("cycles"));
}

TEST(Cli, BadInputGetsOneLineAndExitTwo) {
  const fs::path bad = scratch("bad.node");
  write(bad, "4 3 0 0\n0 0 0 0\n1 1 0 0\n");  // truncated: 2 of 4 points
  write(scratch("bad.ele"), "1 4 0\n0 0 1 2 3\n");
  Outcome r = vobench("check --algorithm mpvo --input " + bad.string() + " --views 1 --size 8x8");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("bad.node"), std::string::npos) << r.out;
  r = vobench("check --algorithm mpvo --dataset gap --set nx=-3");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("nx"), std::string::npos) << r.out;
  r = vobench("check --algorithm nosuch --dataset gap");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("unknown orderer"), std::string::npos) << r.out;
  r = vobench("check --algorithm centroid:key=sideways --dataset gap");
  EXPECT_EQ(r.code, 2) << r.out;
  r = vobench(std::string("check --algorithm mpvo ") + kSmallGap + " --size 0x10");
  EXPECT_EQ(r.code, 2) << r.out;
  r = vobench(std::string("check --algorithm mpvo ") + kSmallGap + " --eye nan,0,0 --target 0,0,0");
  EXPECT_EQ(r.code, 2) << r.out;
  r = vobench("check --algorithm mpvo");
  EXPECT_EQ(r.code, 2) << r.out;
}

TEST(Cli, RunWritesRecordsAndSkipsThemOnRerun) {
  const fs::path suite = scratch("suite.json");
  write(suite, R"({"name": "t", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
                   "algorithms": ["mpvo", "centroid"], "views": 2, "sizes": ["32x32"],
                   "repeats": 2, "warmup": 0})");
  const fs::path results = scratch("results.jsonl");
  fs::remove(results);
  Outcome r = vobench("run " + suite.string() + " -o " + results.string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(results);
  std::string line;
  int n = 0, contexts = 0, plans = 0;
  std::string run_id;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["schema_version"], 2);
    if (j.value("type", "") == "plan") {  // one per suite run, before its jobs
      EXPECT_EQ(n, 0);
      EXPECT_EQ(contexts, 0);
      EXPECT_EQ(j["jobs"].size(), 4u);
      ++plans;
      continue;
    }
    if (j.value("type", "") == "context") {  // one per run, before its records
      EXPECT_EQ(n, 0);
      ++contexts;
      run_id = j["run_id"];
      for (const char* k : {"cpu", "threads", "libraries", "load_avg", "git_sha", "allocation"})
        EXPECT_TRUE(j["context"].contains(k)) << k;
      continue;
    }
    for (const char* k : {"algorithm", "dataset", "n", "b", "a", "w", "h", "camera", "phases", "total",
                          "prepare", "bytes", "oracle", "run_id", "cycles"})
      EXPECT_TRUE(j.contains(k)) << k;
    EXPECT_FALSE(j.contains("context"));
    EXPECT_EQ(j["run_id"], run_id);
    EXPECT_EQ(j["total"]["samples"].size(), 2u);
    ++n;
  }
  EXPECT_EQ(n, 4);
  EXPECT_EQ(contexts, 1);
  EXPECT_EQ(plans, 1);
  r = vobench("run " + suite.string() + " -o " + results.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("0 records written, 4 already present"), std::string::npos) << r.out;
  // Another setting is another key: a run without the oracle, then the oracle switched on,
  // writes every record again.
  const fs::path suite2 = scratch("suite_nooracle.json"), results2 = scratch("oracle_on.jsonl");
  write(suite2, R"({"name": "t", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
                    "algorithms": ["mpvo", "centroid"], "views": 2, "sizes": ["32x32"],
                    "repeats": 2, "warmup": 0, "oracle": false})");
  fs::remove(results2);
  r = vobench("run " + suite2.string() + " -o " + results2.string());
  ASSERT_EQ(r.code, 0) << r.out;
  r = vobench("run " + suite.string() + " -o " + results2.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("4 records written, 0 already present"), std::string::npos) << r.out;
  const fs::path report = scratch("report");
  r = vobench("report " + results.string() + " -o " + report.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(report / "report.md"));
  EXPECT_TRUE(fs::exists(report / "report.html"));
  EXPECT_FALSE(fs::is_empty(report / "figures"));
}

// The context says how large blocks were allocated: huge pages unless the kernel's mode is
// "never", the build is under AddressSanitizer, or VOBENCH_HUGE_PAGES=0 turned them off.
TEST(Cli, RunContextSaysHowLargeBlocksAreAllocated) {
  const fs::path suite = scratch("alloc_suite.json");
  write(suite, R"({"name": "t", "datasets": [{"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 2}}],
                   "algorithms": ["centroid"], "views": 1, "sizes": ["16x16"], "repeats": 1, "warmup": 0})");
  std::ifstream mode_in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(mode_in, mode);
#if defined(__SANITIZE_ADDRESS__)
  const bool asan = true;
#else
  const bool asan = false;
#endif
  for (const std::string env : {"", "VOBENCH_HUGE_PAGES=0 "}) {
    const fs::path results = scratch("alloc.jsonl");
    fs::remove(results);
    const auto r = vob::test::run_command(env + VOB_BINARY + " run " + suite.string() + " -o " + results.string() + " 2>&1");
    ASSERT_EQ(r.code, 0) << r.out;
    std::ifstream in(results);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));  // the suite's plan line
    ASSERT_TRUE(std::getline(in, line));
    const auto a = nlohmann::json::parse(line)["context"]["allocation"];
    ASSERT_TRUE(a.is_object()) << line;
    const bool expect_on = env.empty() && !asan && !mode.empty() && mode.find("[never]") == std::string::npos;
    EXPECT_EQ(a["huge_pages"], expect_on) << a.dump();
    EXPECT_EQ(a["kernel_thp"], mode.empty() ? "unknown" : mode) << a.dump();
    EXPECT_EQ(a["min_bytes"], 2 << 20) << a.dump();
    EXPECT_EQ(a["reuse_max_bytes"], 512 << 20) << a.dump();
    EXPECT_EQ(a["reuse_max_blocks"], 32) << a.dump();
    if (!env.empty()) {
      EXPECT_EQ(a["why_off"], asan ? "not built under AddressSanitizer" : "VOBENCH_HUGE_PAGES=0");
    }
  }
}

TEST(Cli, MalformedSuiteIsBadInput) {
  const fs::path suite = scratch("broken.json");
  write(suite, "{\"name\": \"t\", \"datasets\": [");
  const Outcome r = vobench("run " + suite.string() + " -o " + scratch("x.jsonl").string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("broken.json"), std::string::npos) << r.out;
}

namespace {
// Lines of the output (stdout and stderr together), without empty ones.
std::vector<std::string> lines_of(const std::string& out) {
  std::vector<std::string> v;
  size_t start = 0;
  while (start < out.size()) {
    const size_t end = out.find('\n', start);
    const std::string line = out.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty()) v.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return v;
}
}  // namespace

TEST(Cli, UsageErrorsAreOneLineNamingSubcommandAndOption) {
  for (const auto& [args, prefix] : std::vector<std::pair<std::string, std::string>>{
           {"check --algorithm mpvo --views 0", "vobench: check: --views: "},
           {"check --algorithm mpvo --views 4294967298", "vobench: check: --views: "},
           {"check --algorithm mpvo --view-index -1", "vobench: check: --view-index: "},
           {"order --algorithm mpvo --orbit -3 -o x.json", "vobench: order: --orbit: "},
           {"check --algorithm mpvo --views 1000000", "vobench: check: --views: "},
           {"check --algorithm mpvo --supersample 17", "vobench: check: --supersample: "},
           {"check --algorithm mpvo --views", "vobench: check: --views"},
           {"generate --dataset gap", "vobench: generate: --output"}}) {
    const Outcome r = vobench(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 1u) << args << "\n" << r.out;
    EXPECT_EQ(lines[0].rfind(prefix, 0), 0u) << args << "\n" << r.out;
  }
}

TEST(Cli, OptionsThatWouldBeIgnoredAreRefusedWithTheReason) {
  const std::string check = std::string("check --algorithm mpvo ") + kSmallGap;
  for (const auto& [args, names] : std::vector<std::pair<std::string, std::string>>{
           {check + " --fov 30", "--fov"},  // a view set fits its own field of view
           {check + " --fov 0 --eye 3,0,0 --target 0,0,0", "--fov"},
           {check + " --eye 3,0,0 --target 0,0,0 --views 5", "--views"},
           {check + " --eye 3,0,0 --target 0,0,0 --fov 30 --ortho 2", "--fov"},
           {check + " --orbit 4 --views 6", "--views"},
           {check + " --view-index 14", "--view-index"},
           {check + " --set nx=5", "--set"},  // given twice
           {"check --algorithm btf " + std::string(kSmallGap), "btf"},
           {"order --algorithm mpvo " + std::string(kSmallGap) + " -o x.json", "--view-index"}}) {
    const Outcome r = vobench(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 1u) << args << "\n" << r.out;
    EXPECT_NE(lines[0].find(names), std::string::npos) << args << "\n" << r.out;
  }
}

TEST(Cli, UnknownNamesAreRefusedBeforeTheDatasetIsMade) {
  // The default gap has 1.5 million cells: refusing within the test's time means the name
  // was checked first. The message is the only output.
  for (const std::string& args : {std::string("check --algorithm nosuch --dataset gap"),
                                  std::string("check --algorithm havs:k=99 --dataset gap"),
                                  std::string("check --algorithm mpvo --dataset gap --set colour=3"),
                                  std::string("check --algorithm mpvo --dataset gap --size 0x1")}) {
    const Outcome r = vobench(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_EQ(lines_of(r.out).size(), 1u) << args << "\n" << r.out;
  }
}

TEST(Cli, SuiteErrorsNameTheFileAndEntryBeforeAnyDatasetIsMade) {
  const fs::path suite = scratch("late-error.json");
  // datasets[0] is valid and would print a progress line if it were generated first.
  write(suite, R"({"name": "t", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}},
                   {"name": "gap", "set": {"nx": 100000}}], "algorithms": ["mpvo"], "views": 2})");
  Outcome r = vobench("run " + suite.string() + " -o " + scratch("late.jsonl").string());
  EXPECT_EQ(r.code, 2) << r.out;
  auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  EXPECT_NE(lines[0].find("late-error.json: datasets[1].set: gap: parameter nx"), std::string::npos) << r.out;
  write(suite, R"({"name": "t", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
                   "algorithms": ["mpvo"], "views": 4294967298})");
  r = vobench("run " + suite.string() + " -o " + scratch("late.jsonl").string());
  EXPECT_EQ(r.code, 2) << r.out;
  lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  EXPECT_NE(lines[0].find("late-error.json: views: "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(scratch("late.jsonl")));
}

TEST(Cli, ReportRefusesALineThatIsNotARecord) {
  const fs::path results = scratch("not-records.jsonl");
  write(results, "[1, 2]\n");
  const Outcome r = vobench("report " + results.string() + " -o " + scratch("rep").string());
  EXPECT_EQ(r.code, 2) << r.out;
  const auto lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  EXPECT_NE(lines[0].find("not-records.jsonl: line 1: is not a JSON object"), std::string::npos) << r.out;
}
