// ParaView outputs through the vobench program: `order --vtu` (cell arrays order_rank,
// violating_fragments, in_cycle) and `check --images` (.vti violation maps, .pvcc cameras),
// each read back with VTK's own readers and XML parser.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>

#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "tests/support/test_util.h"

namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) { return vob::test::scratch_path("vobench_paraview", name); }

vob::test::CommandOutput vobench(const std::string& args) {
  return vob::test::run_command(std::string(VOB_BINARY) + " " + args + " 2>&1");
}

std::vector<double> values(vtkDataArray* a) {
  std::vector<double> v;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i) v.push_back(a->GetComponent(i, 0));
  return v;
}

// ORDER.json and the .vtu of one `order` run, checked against each other.
void check_order_vtu(const std::string& args, const std::string& name, bool expect_violations) {
  const fs::path json = scratch(name + ".json"), vtu = scratch(name + ".vtu");
  const auto r = vobench("order " + args + " --check -o " + json.string() + " --vtu " + vtu.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* ug = reader->GetOutput();
  const size_t n = j["primitives"].get<size_t>();
  ASSERT_EQ(size_t(ug->GetNumberOfCells()), n);
  const auto rank = values(ug->GetCellData()->GetArray("order_rank"));
  const auto violating = values(ug->GetCellData()->GetArray("violating_fragments"));
  const auto cycle = values(ug->GetCellData()->GetArray("in_cycle"));
  ASSERT_EQ(rank.size(), n);
  ASSERT_EQ(violating.size(), n);
  ASSERT_EQ(cycle.size(), n);
  const auto order = j["order"].get<std::vector<int>>();
  for (size_t i = 0; i < order.size(); ++i) EXPECT_EQ(rank[order[i]], double(i));
  const double sum = std::accumulate(violating.begin(), violating.end(), 0.0);
  EXPECT_EQ(sum, j["oracle"]["violating_fragments"].get<double>());
  EXPECT_EQ(sum > 0, expect_violations) << sum;
  const auto listed = j["cycles"]["primitives"].get<std::set<int>>();
  EXPECT_EQ(std::accumulate(cycle.begin(), cycle.end(), 0.0), double(listed.size()));
  for (const int c : listed) EXPECT_EQ(cycle[c], 1.0);
}
}  // namespace

TEST(ParaviewFiles, OrderVtuHasRankViolationsAndCyclesPerCell) {
  // A heuristic with violations, an exact orderer without, and one that meets cycles.
  check_order_vtu("-a centroid --dataset helix --set cells=3000 --view-index 0 --size 128x128", "centroid", true);
  check_order_vtu("-a sxmpvo --dataset helix --set cells=3000 --view-index 0 --size 128x128", "sxmpvo", false);
  check_order_vtu("-a mpvo --dataset cycle --view-index 0 --size 128x128", "cycle", true);
}

TEST(ParaviewFiles, OrderVtuRefusesTrianglesWithOneLine) {
  const auto r = vobench("order -a stencil-layers --dataset sphere --view-index 0 -o " +
                         scratch("t.json").string() + " --vtu " + scratch("t.vtu").string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("--vtu"), std::string::npos) << r.out;
}

TEST(ParaviewFiles, CheckImagesWritesViolationVtiAndParaviewCamera) {
  const fs::path dir = scratch("images");
  const auto r = vobench("check -a centroid --dataset helix --set cells=3000 --views 2 --size 96x64 --json --images " +
                         dir.string());
  ASSERT_EQ(r.code, 1) << r.out;  // the heuristic violates
  const nlohmann::json out = nlohmann::json::parse(r.out.substr(r.out.find('{')));
  for (const auto& v : out["views"]) {
    const std::string stem = (dir / ("view" + std::to_string(v["view_index"].get<int>()))).string();
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName((stem + "-violations.vti").c_str());
    reader->Update();
    int dims[3];
    reader->GetOutput()->GetDimensions(dims);
    EXPECT_EQ(dims[0], 96);
    EXPECT_EQ(dims[1], 64);
    const auto mask = values(reader->GetOutput()->GetPointData()->GetArray("violating"));
    ASSERT_EQ(mask.size(), size_t(96 * 64));
    EXPECT_EQ(std::accumulate(mask.begin(), mask.end(), 0.0), v["violating_pixels"].get<double>());

    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((stem + ".pvcc").c_str());
    ASSERT_EQ(parser->Parse(), 1) << stem << ".pvcc";
    vtkXMLDataElement* root = parser->GetRootElement();
    ASSERT_STREQ(root->GetName(), "PVCameraConfiguration");
    vtkXMLDataElement* proxy = root->FindNestedElementWithName("Proxy");
    ASSERT_NE(proxy, nullptr);
    vtkXMLDataElement* pos = proxy->FindNestedElementWithNameAndAttribute("Property", "name", "CameraPosition");
    ASSERT_NE(pos, nullptr);
    ASSERT_EQ(pos->GetNumberOfNestedElements(), 3);
    for (int i = 0; i < 3; ++i) {
      double value = 0;
      pos->GetNestedElement(i)->GetScalarAttribute("value", value);
      EXPECT_DOUBLE_EQ(value, v["camera"]["eye"][i].get<double>());
    }
    EXPECT_NE(proxy->FindNestedElementWithNameAndAttribute("Property", "name", "CameraViewAngle"), nullptr);
  }
}
