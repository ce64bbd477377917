// Suite validation: a suite is checked completely before any work, and every message names
// the suite file and the entry.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "datasets/datasets.h"
#include "harness/bench/reproduction.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"

using namespace vob;

namespace {
nlohmann::json valid() {
  return nlohmann::json::parse(R"({"name": "s",
      "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}, {"name": "sphere"}],
      "algorithms": ["mpvo", "havs:k=4", "all"], "views": 5, "view_indices": [0, 4],
      "sizes": ["64x48"], "repeats": 2, "warmup": 0, "zoom": 1.5, "ortho": false,
      "oracle": true, "supersample": 2, "image_error": true, "image_views": [1],
      "images_of_violations": false, "comment": "anything"})");
}

// The message of the InputError that from_json throws ("" when it throws none).
std::string error_of(const nlohmann::json& j) {
  try {
    SuiteSpec::from_json(j, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

TEST(SuiteValidation, AcceptsEveryKey) {
  const SuiteSpec s = SuiteSpec::from_json(valid(), "s.json");
  EXPECT_EQ(s.views, 5);
  EXPECT_EQ(s.view_indices, (std::vector<int>{0, 4}));
  EXPECT_EQ(s.sizes[0], std::make_pair(64, 48));
  EXPECT_EQ(s.supersample, 2);
  EXPECT_DOUBLE_EQ(s.zoom, 1.5);
  EXPECT_EQ(s.algorithms.size(), 3u);
}

TEST(SuiteValidation, IntegersAreRangeCheckedBeforeNarrowing) {
  auto j = valid();
  j["views"] = (int64_t(1) << 32) + 2;  // would wrap to 2 as an int
  EXPECT_TRUE(starts_with(error_of(j), "s.json: views: ")) << error_of(j);
  j["views"] = 0;  // nlohmann holds it unsigned
  EXPECT_TRUE(starts_with(error_of(j), "s.json: views: ")) << error_of(j);
  j["views"] = 10001;
  EXPECT_TRUE(starts_with(error_of(j), "s.json: views: ")) << error_of(j);
  j = valid();
  j["repeats"] = (int64_t(1) << 31);
  EXPECT_TRUE(starts_with(error_of(j), "s.json: repeats: ")) << error_of(j);
  j = valid();
  j["repeats"] = 0;
  EXPECT_TRUE(starts_with(error_of(j), "s.json: repeats: ")) << error_of(j);
  j = valid();
  j["views"] = 2.5;
  EXPECT_TRUE(starts_with(error_of(j), "s.json: views: ")) << error_of(j);
  j = valid();
  j["view_indices"] = {0, 5};  // views is 5
  EXPECT_TRUE(starts_with(error_of(j), "s.json: view_indices[1]: ")) << error_of(j);
  j = valid();
  j["datasets"][0]["set"]["nx"] = (int64_t(1) << 32) + 2;
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[0].set: gap: parameter nx")) << error_of(j);
}

TEST(SuiteValidation, NamesTheEntryOfEveryDatasetAndAlgorithm) {
  auto j = valid();
  j["datasets"][1]["set"] = {{"subdiv", 9}};
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[1].set: sphere: parameter subdiv")) << error_of(j);
  j = valid();
  j["datasets"][1]["name"] = "nope";
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[1].name: ")) << error_of(j);
  j = valid();
  j["datasets"][1]["set"] = {{"colour", 1}};
  EXPECT_NE(error_of(j).find("datasets[1].set: sphere: parameter colour"), std::string::npos) << error_of(j);
  j = valid();
  j["datasets"][0]["set"]["gaps"] = 4;  // needs nz > gaps
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[0].set: ")) << error_of(j);
  j = valid();
  j["datasets"][1] = {{"input", "no-such-file.vtu"}};
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[1].input: ")) << error_of(j);
  j = valid();
  j["algorithms"][1] = "havs:k=99";
  EXPECT_TRUE(starts_with(error_of(j), "s.json: algorithms[1]: ")) << error_of(j);
  j = valid();
  j["algorithms"][0] = "nope";
  EXPECT_TRUE(starts_with(error_of(j), "s.json: algorithms[0]: ")) << error_of(j);
  j = valid();
  j["algorithms"][0] = "mpvo:zzz=1";
  EXPECT_TRUE(starts_with(error_of(j), "s.json: algorithms[0]: ")) << error_of(j);
  // No message names a command-line option.
  for (const char* key : {"sizes", "views", "zoom"}) {
    j = valid();
    j[key] = "0x0";
    EXPECT_EQ(error_of(j).find("--"), std::string::npos) << error_of(j);
  }
  j = valid();
  j["sizes"] = {"64x48", "0x5"};
  EXPECT_TRUE(starts_with(error_of(j), "s.json: sizes[1]: ")) << error_of(j);
}

TEST(SuiteValidation, RefusesWrongTypesAndUnknownKeys) {
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"ortho", "yes"}, {"oracle", 1}, {"name", 5}, {"datasets", nlohmann::json::array()},
           {"algorithms", "mpvo"}, {"colour", 1}, {"image_views", 0}}) {
    auto j = valid();
    j[key] = value;
    EXPECT_TRUE(starts_with(error_of(j), "s.json: " + key)) << key << ": " << error_of(j);
  }
  auto j = valid();
  j["datasets"][0]["sets"] = nlohmann::json::object();
  EXPECT_TRUE(starts_with(error_of(j), "s.json: datasets[0].sets: ")) << error_of(j);
  EXPECT_TRUE(starts_with(error_of(nlohmann::json::array()), "s.json: suite: ")) << error_of(nlohmann::json::array());
}

TEST(SuiteValidation, ChecksGeneratorParametersWithoutGenerating) {
  // 480 million tetrahedra are within gap's limits; generating them would need tens of GB,
  // so this passes only if validation generates nothing.
  auto j = valid();
  j["datasets"][0]["set"] = {{"nx", 1000}, {"ny", 1000}, {"nz", 80}};
  j["datasets"][1] = {{"name", "sparse"}, {"set", {{"nx", 512}, {"ny", 512}, {"nz", 512}, {"blobs", 10000}}}};
  EXPECT_EQ(error_of(j), "");
  Params p("gap");
  p.set("nx", "1000");
  p.set("ny", "1000");
  p.set("nz", "80");
  EXPECT_NO_THROW(check_dataset_params("gap", p));
  p.set("gaps", "96");
  EXPECT_THROW(check_dataset_params("gap", p), InputError);
}

TEST(SuiteValidation, SizesAreStrict) {
  EXPECT_EQ(parse_size("640x480"), std::make_pair(640, 480));
  for (const char* bad : {"+5x5", " 5x5", "5x5 ", "5x5x5", "4294967297x5", "1e2x5", "x5", "5x", "0x5",
                          "16385x5", "-5x5", "5X5"})
    EXPECT_THROW(parse_size(bad), InputError) << bad;
  try {
    parse_size("0x5", "s.json: sizes[2]");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), "s.json: sizes[2]: '0x5': ")) << e.what();
  }
}

TEST(SuiteValidation, EverySuiteOfTheRepositoryIsValid) {
  // The validation must not refuse what `vobench run` and the reproductions run: the plain
  // suites at the top, and every reproduction file at every scale.
  const std::string dir = std::string(VOB_SOURCE_DIR) + "/datasets/suites";
  int suites = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    EXPECT_NO_THROW(SuiteSpec::load(e.path().string())) << e.path();
    ++suites;
  }
  EXPECT_GE(suites, 3);
  const auto reproductions = list_reproductions(dir);
  EXPECT_GE(reproductions.size(), 25u);  // the 25 of issue 12
  for (const auto& r : reproductions)
    for (const char* scale : {"tiny", "default", "full"})
      EXPECT_NO_THROW(load_reproduction(r.path, scale, dir)) << r.name << " at " << scale;
}

// "vtk_render" (vobench-vtk's orderers) is checked with the suite, before vobench run starts.
TEST(SuiteValidation, ChecksTheVtkRenderEntry) {
  nlohmann::json j = valid();
  EXPECT_FALSE(SuiteSpec::from_json(j, "s.json").vtk_render);
  j["vtk_render"] = {{"algorithms", {"xmpvo", "centroid:key=view"}}, {"repeats", 2}, {"extinction", 4}};
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  ASSERT_TRUE(s.vtk_render);
  EXPECT_EQ(s.vtk_render->algorithms, (std::vector<std::string>{"xmpvo", "centroid:key=view"}));
  EXPECT_EQ(s.vtk_render->repeats, 2);
  EXPECT_EQ(s.source["vtk_render"], j["vtk_render"]);  // what vobench-vtk is handed
  const std::vector<std::pair<nlohmann::json, std::string>> bad = {
      {{{"algorithms", {"btf"}}}, "s.json: vtk_render.algorithms: btf: orders no cells"},
      {{{"algorithms", {"nope"}}}, "s.json: vtk_render.algorithms: "},
      {{{"algorithms", nlohmann::json::array()}}, "s.json: vtk_render.algorithms: must be a non-empty list"},
      {{{"algorithms", {"xmpvo"}}, {"repeats", 0}}, "s.json: vtk_render.repeats: "},
      {{{"algorithms", {"xmpvo"}}, {"views", 3}}, "s.json: vtk_render"},
      {"xmpvo", "s.json: vtk_render: must be an object"}};
  for (const auto& [entry, message] : bad) {
    j["vtk_render"] = entry;
    EXPECT_TRUE(starts_with(error_of(j), message)) << error_of(j);
  }
}
