// One verdict per orderer, end to end: `vobench check` judges HAVS on what it composites,
// prints the same count the record of `vobench run` stores in `oracle`, writes the
// violation map, and refuses --supersample > 1 for it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/render/compositor.h"
#include "tests/support/test_util.h"

namespace fs = std::filesystem;

namespace {
using Outcome = vob::test::CommandOutput;  // stdout and stderr together
Outcome vobench(const std::string& args) { return vob::test::run_vobench(VOB_BINARY, args); }
nlohmann::json json_of(const Outcome& r) { return nlohmann::json::parse(r.out.substr(r.out.find('{'))); }

const char* kTinyConvex = "--dataset gap --set nx=3 --set ny=3 --set nz=3 --set gaps=0";
const char* kHelix = "--dataset helix --set cells=2000";
}  // namespace

TEST(VerdictCli, HavsLargeKOnATinyConvexMeshExitsZero) {
  const Outcome r = vobench(std::string("check --algorithm havs:k=16 ") + kTinyConvex + " --views 6 --size 48x48");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("derived cell order"), std::string::npos) << r.out;
}

TEST(VerdictCli, HavsSupersampleIsRefused) {
  const Outcome r = vobench(std::string("check --algorithm havs:k=4 ") + kTinyConvex + " --views 1 --supersample 2");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("composites"), std::string::npos) << r.out;
}

// The count `check` prints (and its --json) is the record's oracle.violating_pixels; the
// violation maps of both mark exactly that many pixels.
TEST(VerdictCli, HavsK1OnHelixSameCountInCheckAndRun) {
  vob::test::TempDir dir;
  const Outcome c = vobench(std::string("check --algorithm havs:k=1 ") + kHelix +
                            " --views 4 --view-index 1 --size 64x64 --json --images " + dir.file("check"));
  ASSERT_EQ(c.code, 1) << c.out;
  const nlohmann::json cj = json_of(c);
  ASSERT_EQ(cj.at("views").size(), 1u);
  const nlohmann::json& v = cj.at("views")[0];
  EXPECT_EQ(v.at("judged"), "composited");
  const int64_t violating = v.at("violating_pixels");
  EXPECT_GT(violating, 0);
  EXPECT_EQ(v.at("oracle_cell_order").at("judged"), "derived cell order");
  EXPECT_EQ(vob::marked_pixels(vob::read_png(dir.file("check/view1-violations.png"))), violating);

  std::ofstream(dir.file("suite.json")) << R"({"name": "verdict", "datasets": [{"name": "helix",
      "set": {"cells": 2000}}], "algorithms": ["havs:k=1"], "sizes": ["64x64"], "views": 4,
      "view_indices": [1], "repeats": 1, "warmup": 0, "image_views": [1]})";
  fs::create_directories(dir.file("out"));
  const Outcome r = vobench("run " + dir.file("suite.json") + " -o " + dir.file("out/results.jsonl"));
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(dir.file("out/results.jsonl"));
  std::string line;
  int records = 0;
  while (std::getline(in, line)) {
    const auto rec = nlohmann::json::parse(line);
    if (!rec.contains("algorithm")) continue;  // context lines
    ++records;
    EXPECT_EQ(rec.at("oracle").at("judged"), "composited");
    EXPECT_EQ(rec.at("oracle").at("violating_pixels").get<int64_t>(), violating);
    EXPECT_EQ(rec.at("oracle_cell_order").at("violating_pixels"), v.at("oracle_cell_order").at("violating_pixels"));
    const std::string map = rec.at("images").at("violations");
    EXPECT_FALSE(fs::path(map).is_absolute()) << map;
    EXPECT_EQ(vob::marked_pixels(vob::read_png(dir.file("out/" + map))), violating);
  }
  EXPECT_EQ(records, 1);
}
