// Interpenetrating volumes through the vobench program: check refuses them (exit 2, one line
// naming two cells), validate lists the pairs, run marks the record an input fault.
// Data: tests/data/two_boxes.vtk, two boxes meshed separately by gmsh (two_boxes.geo), and
// two Kuhn blocks built here.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "datasets/datasets.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

namespace fs = std::filesystem;

namespace {
struct Outcome {
  int code;
  std::string out, err;
};

Outcome vobench(const std::string& args) {
  const fs::path err = fs::temp_directory_path() / ("vobench_overlap_err_" + std::to_string(getpid()));
  const std::string cmd = std::string(VOB_BINARY) + " " + args + " 2>" + err.string();
  const vob::test::CommandOutput r = vob::test::run_command(cmd);
  std::ifstream in(err);
  std::string e((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {r.code, r.out, e};
}

fs::path scratch(const std::string& name) { return vob::test::scratch_path("vobench_overlap", name); }

const std::string kGmsh = std::string(VOB_TEST_DATA) + "/two_boxes.vtk";

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

// Two Kuhn blocks of 48 cells overlapping by part of a cell, written as .vtu.
std::string blocks_file() {
  const fs::path p = scratch("blocks.vtu");
  vob::CellMesh m = vob::test::interpenetrating_blocks(2);
  vob::validate_cell_mesh(m, "blocks");
  vob::write_scene(vob::Scene::from_mesh("blocks", std::move(m)), p.string());
  return p.string();
}
}  // namespace

TEST(CliOverlap, CheckRefusesInterpenetratingVolumesNamingTwoCells) {
  for (const std::string& file : {kGmsh, blocks_file()}) {
    for (const char* algo : {"mpvo", "sxmpvo"}) {
      const Outcome r = vobench(std::string("check --algorithm ") + algo + " --input " + file +
                                " --views 2 --size 64x64");
      EXPECT_EQ(r.code, 2) << r.out << r.err;
      EXPECT_EQ(lines(r.err), 1) << r.err;
      EXPECT_NE(r.err.find(fs::path(file).filename().string()), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("cells "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(" overlap (sample at pixel "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("the input has no visibility order"), std::string::npos) << r.err;
    }
  }
}

// Warped quads (overlapping_twisted_bar: neighbours sharing only an edge overlap as the
// oracle models them): check and validate both refuse the file and name the cause; a block
// whose quads are planar only to rounding passes both.
TEST(CliOverlap, CheckAndValidateAgreeOnWarpedQuads) {
  const fs::path bar = scratch("twisted.vtu"), block = scratch("rotated.vtu");
  vob::write_scene(vob::Scene::from_mesh("twisted", vob::test::overlapping_twisted_bar(2, 0.05)), bar.string());
  vob::write_scene(vob::Scene::from_mesh("rotated", vob::test::rotated(vob::test::hex_block(3), {0.3, 0.5, 0.8}, 0.651)),
                   block.string());
  Outcome r = vobench("check --algorithm xmpvo --input " + bar.string() + " --views 4 --size 128x128");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(" overlap (sample at pixel "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("quads are not planar"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the oracle takes each quad as one plane"), std::string::npos) << r.err;
  r = vobench("validate " + bar.string());
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("(only as the oracle models them: "), std::string::npos) << r.out;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cells 0 and 3 overlap by "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" as the oracle models them"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("quads are not planar"), std::string::npos) << r.err;
  r = vobench("validate --json " + bar.string());
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["overlapping_pairs"], 2);
  EXPECT_EQ(j["oracle_model"]["overlapping_pairs"].size(), 2u);
  EXPECT_EQ(j["oracle_model"]["warped_cells"], 8);
  r = vobench("check --algorithm xmpvo --input " + block.string() + " --views 4 --size 128x128");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  r = vobench("validate " + block.string());
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("0 overlapping by more than its threshold"), std::string::npos) << r.out;
}

TEST(CliOverlap, ValidateListsThePairsAndExitsTwo) {
  Outcome r = vobench("validate " + kGmsh);
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("interpenetrating pairs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  cells "), std::string::npos) << r.out;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("interpenetrate"), std::string::npos) << r.err;
  r = vobench("validate --json --input " + kGmsh);
  EXPECT_EQ(r.code, 2);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_GT(j["overlapping_pairs"].get<int>(), 20);  // more than the text listing shows
  EXPECT_EQ(j["pairs"].size(), j["overlapping_pairs"].get<size_t>());
  EXPECT_NE(r.err.find("cells " + std::to_string(j["pairs"][0][0].get<int>()) + " and " +
                       std::to_string(j["pairs"][0][1].get<int>())),
            std::string::npos)
      << r.err;
}

TEST(CliOverlap, ValidateOfAValidMeshIsClean) {
  for (const char* how : {"", "--exhaustive "}) {
    const Outcome r =
        vobench(std::string("validate ") + how + "--dataset gap --set nx=4 --set ny=4 --set nz=6 --set gaps=2");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(", 0 interpenetrating pairs"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(*how ? "exhaustive search" : "certified by the boundary check"), std::string::npos)
        << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
  }
}

// The summary line counts in the singular where a count is 1 (it said "1 components").
TEST(CliOverlap, ValidateSummarySaysOneComponent) {
  vob::CellMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.add_cell(vob::CellType::Tetra, {0, 1, 2, 3});
  const fs::path p = scratch("one.vtu");
  vob::write_scene(vob::Scene::from_mesh("one", std::move(m)), p.string());
  const Outcome r = vobench("validate " + p.string());
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(": 1 cell, 0 interpenetrating pairs (certified by the boundary check: 4 boundary triangles, "
                       "0 exact pair tests, 1 component; "),
            std::string::npos)
      << r.out;
}

TEST(CliOverlap, ValidateListsEveryPairWhenTheBoundaryCheckFindsOne) {
  const Outcome fast = vobench("validate --json " + kGmsh);
  const Outcome full = vobench("validate --json --exhaustive " + kGmsh);
  EXPECT_EQ(fast.code, 2);
  EXPECT_EQ(full.code, 2);
  const auto f = nlohmann::json::parse(fast.out), e = nlohmann::json::parse(full.out);
  EXPECT_EQ(f["certificate"]["result"], "overlap");
  EXPECT_EQ(f["method"], "exhaustive");
  EXPECT_FALSE(e.contains("certificate"));
  EXPECT_EQ(f["pairs"], e["pairs"]);
}

TEST(CliOverlap, ValidateFullOptionRefusesBeforeOrdering) {
  Outcome r = vobench("check --validate full --algorithm mpvo --input " + blocks_file() +
                      " --views 1 --size 16x16");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("interpenetrate"), std::string::npos) << r.err;
  r = vobench("check --validate full --algorithm mpvo --dataset gap --set nx=3 --set ny=3 "
              "--set nz=4 --views 1 --size 16x16");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  r = vobench("check --validate sometimes --algorithm mpvo --dataset gap");
  EXPECT_EQ(r.code, 2);
}

// `vobench run OPTIONS SUITE -o RESULTS` of a one-view mpvo suite over the interpenetrating
// gmsh boxes; `results` (named after `tag`) is removed first and its path returned in it.
Outcome run_gmsh_suite(const std::string& tag, const std::string& options, fs::path& results) {
  const fs::path suite = scratch("suite" + tag + ".json");
  std::ofstream(suite) << R"({"name": "t", "datasets": [{"input": ")" << kGmsh << R"("}],
                   "algorithms": ["mpvo"], "views": 1, "sizes": ["48x48"],
                   "repeats": 1, "warmup": 0})";
  results = scratch("results" + tag + ".jsonl");
  fs::remove(results);
  return vobench("run " + options + suite.string() + " -o " + results.string());
}

TEST(CliOverlap, RunMarksTheRecordAnInputFault) {
  fs::path results;
  const Outcome r = run_gmsh_suite("", "", results);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::ifstream in(results);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));  // the suite's plan line
  ASSERT_TRUE(std::getline(in, line));  // the run's context line
  ASSERT_TRUE(std::getline(in, line));
  const auto j = nlohmann::json::parse(line);
  ASSERT_TRUE(j.contains("input_fault")) << line.substr(0, 400);
  EXPECT_GT(j["input_fault"]["overlapping_pairs"].get<int>(), 0);
  EXPECT_EQ(j["input_fault"]["overlapping_pairs"], j["oracle"]["overlapping_pairs"]);
  EXPECT_FALSE(j["input_fault"]["examples"].empty());
  EXPECT_NE(r.err.find("input fault: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(", 0 with oracle violations"), std::string::npos) << r.err;
}

TEST(CliOverlap, RunWithValidateFullRefusesTheDatasetBeforeMeasuring) {
  fs::path results;
  const Outcome r = run_gmsh_suite("-full", "--validate full ", results);
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("interpenetrate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("two_boxes"), std::string::npos) << r.err;
  // Nothing measured: at most the suite's plan line (written before its jobs), no record.
  std::ifstream in(results);
  for (std::string line; std::getline(in, line);)
    EXPECT_EQ(nlohmann::json::parse(line).value("type", ""), "plan") << line.substr(0, 200);
}
