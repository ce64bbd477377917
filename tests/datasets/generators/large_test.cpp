// Full-size generation is fast: the paper's 1.5M-cell gap mesh and a 1M-cell helix, built
// and validated, with times printed for the record.
#include <chrono>
#include <cstdio>

#include "datasets/generators/gap.h"
#include "datasets/generators/helix.h"
#include "harness/scene/mesh_faces.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The helix at `cells` cells, generated and validated, with the time printed.
Scene timed_helix(const char* cells) {
  Params p;
  p.set("cells", cells);
  const auto t0 = std::chrono::steady_clock::now();
  Scene s = make_dataset("helix", p);
  std::printf("helix cells=%s: %zu cells, generate+validate %.2f s\n", cells, s.mesh().num_cells(),
              seconds_since(t0));
  return s;
}
}  // namespace

TEST(LargeDatasets, FullGapWith95Gaps) {
  Params p;
  p.set("gaps", "95");
  auto t0 = std::chrono::steady_clock::now();
  const Scene s = make_dataset("gap", p);  // generate + validate
  const double make_s = seconds_since(t0);
  EXPECT_EQ(s.mesh().num_cells(), 1500000u);
  t0 = std::chrono::steady_clock::now();
  const MeshFaces f = build_mesh_faces(s.mesh(), "gap");
  const double faces_s = seconds_since(t0);
  // 50,000 exterior faces for the block plus 10,000 per gap (Cook et al. section 5.2).
  EXPECT_EQ(f.boundary.size(), 50000u + 95u * 10000u);
  std::printf("gap 50x50x100 gaps=95: %zu cells, generate+validate %.2f s, faces %.2f s\n",
              s.mesh().num_cells(), make_s, faces_s);
}

TEST(LargeDatasets, HelixOneMillion) {
  const Scene s = timed_helix("1000000");
  EXPECT_NEAR(double(s.mesh().num_cells()), 1e6, 1e5);
  EXPECT_NO_THROW(build_mesh_faces(s.mesh(), "helix"));
}

TEST(LargeDatasets, HelixAtThePapersLargestSize) {
  const Scene s = timed_helix("4500000");
  EXPECT_NEAR(double(s.mesh().num_cells()), 4.5e6, 4.5e5);
}

TEST(LargeDatasets, GenerationAloneAtFullSize) {
  auto t0 = std::chrono::steady_clock::now();
  const CellMesh gap = make_gap_mesh({});
  const double gap_s = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  validate_cell_mesh(gap, "gap");
  const double gap_v = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const CellMesh helix = make_helix_mesh({1000000, 3, {0, 0, 0}});
  const double helix_s = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  validate_cell_mesh(helix, "helix");
  const double helix_v = seconds_since(t0);
  EXPECT_EQ(gap.num_cells(), 1500000u);
  std::printf("gap 1.5M: generate %.3f s, validate %.3f s; helix 1M: generate %.3f s, validate %.3f s\n",
              gap_s, gap_v, helix_s, helix_v);
}

TEST(LargeDatasets, DefaultSizesOfEverySyntheticDataset) {
  for (const auto& info : dataset_registry()) {
    if (info.name == "skull" || info.name.rfind("surface-", 0) == 0 || info.name.rfind("tet-", 0) == 0)
      continue;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene s = make_dataset(info.name, Params());
    std::printf("%-14s %-9s %9zu primitives %9zu points %6.2f s\n", info.name.c_str(),
                scene_kind_name(s.kind()), s.num_primitives(),
                s.kind() == SceneKind::Cells ? s.mesh().num_points()
                : s.kind() == SceneKind::Triangles ? s.soup().points.size()
                                                   : s.grid().num_voxels(),
                seconds_since(t0));
    EXPECT_GT(s.num_primitives(), 0u) << info.name;
  }
}
