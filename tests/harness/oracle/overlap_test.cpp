// The oracle's overlapping_pairs: cells whose segments overlap at a sample are an input
// fault it names; touching cells (shared faces, duplicated nodes, non-conforming contact)
// and every generated test scene give none. Cells with warped quads overlap as the oracle
// models them exactly where `validate` (check_overlapping_cells) says they do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "datasets/datasets.h"
#include "harness/oracle/oracle.h"
#include "harness/raster/fragments.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"
#include "harness/scene/mesh_faces.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::test;

namespace {

Scene scene_of(CellMesh m) {
  validate_cell_mesh(m, "test mesh");
  return Scene::from_mesh("test mesh", std::move(m));
}

std::vector<Camera> views(const Scene& s, int n, int size) {
  ViewOptions opt;
  opt.width = opt.height = size;
  std::vector<Camera> v = fibonacci_views(s.bounds(), n, opt);
  opt.ortho = true;
  for (const Camera& c : fibonacci_views(s.bounds(), 2, opt)) v.push_back(c);
  return v;
}

int64_t max_overlapping_pairs(const Scene& s, const std::vector<Camera>& cams) {
  int64_t most = 0;
  for (const Camera& cam : cams)
    most = std::max(most, check_ordering(s, cam, all_primitives(s)).overlapping_pairs);
  return most;
}

}  // namespace

TEST(OracleOverlap, TwoOverlappingTetsAreOnePairWhateverTheOrder) {
  const Vec3 O{0, 0, 0}, X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1}, s{0.3, 0.2, 0.25};
  const Scene scene = scene_of(tet_pair(O, X, Y, Z, O + s, X + s, Y + s, Z + s));
  int seen = 0;
  for (const Camera& cam : views(scene, 6, 64)) {
    const OracleResult a = check_ordering(scene, cam, {0, 1});
    const OracleResult b = check_ordering(scene, cam, {1, 0});
    EXPECT_EQ(a.overlapping_pairs, b.overlapping_pairs);
    ASSERT_LE(a.overlapping_pairs, 1);
    if (a.overlapping_pairs == 0) continue;
    ++seen;
    EXPECT_TRUE(a.input_fault());
    ASSERT_FALSE(a.overlap_examples.empty());
    const auto& e = a.overlap_examples[0];
    EXPECT_EQ(e["cells"], nlohmann::json::array({0, 1}));
    // The segments overlap at the named pixel.
    const auto s0 = e["segments"][0].get<std::vector<double>>();
    const auto s1 = e["segments"][1].get<std::vector<double>>();
    EXPECT_GT(std::min(s0[1], s1[1]) - std::max(s0[0], s1[0]), 0.0);
    EXPECT_EQ(a.to_json()["overlapping_pairs"], 1);
  }
  EXPECT_GE(seen, 6);  // the overlap is a third of the cell: every view sees it
}

// What the oracle sees is a subset of what the exact search finds (cell_overlap.h).
TEST(OracleOverlap, InterpenetratingBlocksAreReported) {
  const Scene scene = scene_of(interpenetrating_blocks(2));
  const int64_t exact = int64_t(find_overlapping_cells(scene.mesh()).pairs.size());
  for (const Camera& cam : views(scene, 4, 64)) {
    const OracleResult r = check_ordering(scene, cam, all_primitives(scene));
    EXPECT_GT(r.overlapping_pairs, 0);
    EXPECT_LE(r.overlapping_pairs, exact);
    for (const auto& e : r.overlap_examples) {
      const int a = e["cells"][0], b = e["cells"][1];
      EXPECT_TRUE(a < 48 && b >= 48) << e.dump();  // one cell of each block
      EXPECT_TRUE(cells_interpenetrate(scene.mesh(), a, b)) << e.dump();
    }
  }
}

TEST(OracleOverlap, TouchingCellsAreNotOverlapping) {
  const Vec3 O{0, 0, 0}, X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
  const CellMesh meshes[] = {
      kuhn_block(3),
      kuhn_block(3, 1.0, 0.25, 3),
      hex_block(3),
      // duplicated nodes: conforming, non-conforming and hexahedral contacts
      append(kuhn_block(2), translated(kuhn_block(2), {2, 0, 0})),
      append(kuhn_block(2), translated(kuhn_block(4, 0.5), {2, 0, 0})),
      append(hex_block(2), translated(hex_block(2), {0, 0, 2})),
      tet_pair(O, X, Y, Z, X, Y, Z, {1, 1, 1}),
      tet_pair(O, X, Y, Z, O, -X, -Y, -Z),
      tet_pair(O, X, Y, Z, {0.3, 0.2, 0}, {1.3, 0.2, 0}, {0.3, 1.2, 0}, {0.3, 0.2, -1}),
  };
  for (const CellMesh& m : meshes) {
    const Scene scene = scene_of(m);
    EXPECT_EQ(max_overlapping_pairs(scene, views(scene, 8, 96)), 0) << m.num_cells() << " cells";
  }
}

// Every generated cell dataset (the hard cases included, with their own views): no pair.
TEST(OracleOverlap, GeneratedCellDatasetsHaveNone) {
  for (const DatasetInfo& info : dataset_registry()) {
    if (info.kind != SceneKind::Cells || info.name.rfind("tet-", 0) == 0) continue;  // real data: downloads
    Params p(info.name);
    if (info.name == "gap") p.set("nx", "8"), p.set("ny", "8"), p.set("nz", "12"), p.set("gaps", "3");
    const Scene scene = make_dataset(info.name, p);
    const std::vector<Camera> cams = info.views ? info.views(scene, 96, 96) : views(scene, 6, 96);
    EXPECT_EQ(max_overlapping_pairs(scene, cams), 0) << info.name;
  }
}

// Warped quads: a twisted bar whose diagonal neighbours overlap as the oracle models them
// (the oracle's planes, cell_planes.h) though their hulls only share an edge. Every pair the
// oracle reports in any view is one `validate` reports, and the views see them all (a twist
// of 0.05 makes the slivers about 0.025 across, wide enough for 128 x 128 pixel centres to
// cross); a block whose quads are planar only to rounding is clean in both.
TEST(OracleOverlap, WarpedNeighboursAreThePairsValidateReports) {
  const Scene bar = scene_of(overlapping_twisted_bar(2, 0.05));
  const CellOverlapReport v = check_overlapping_cells(bar.mesh(), bar.faces());
  ASSERT_FALSE(v.model_pairs.empty());
  std::set<std::pair<int32_t, int32_t>> seen;
  OracleOptions opt;
  opt.max_examples = 1000;
  for (const Camera& cam : views(bar, 8, 128)) {
    const OracleResult r = check_ordering(bar, cam, all_primitives(bar), opt);
    for (const auto& e : r.overlap_examples) {
      const int32_t a = e["cells"][0].get<int32_t>(), b = e["cells"][1].get<int32_t>();
      seen.insert({std::min(a, b), std::max(a, b)});
    }
  }
  const std::vector<std::pair<int32_t, int32_t>> oracle_pairs(seen.begin(), seen.end());
  EXPECT_EQ(oracle_pairs, v.pairs);
  // Rounding-level warps: nothing in either.
  const Scene block = scene_of(rotated(hex_block(3), {0.3, 0.5, 0.8}, 0.651));
  EXPECT_TRUE(check_overlapping_cells(block.mesh(), block.faces()).pairs.empty());
  EXPECT_EQ(max_overlapping_pairs(block, views(block, 8, 128)), 0);
}

// A far eye with a narrow field of view (the block 1e6 and 1e9 away, filling the image):
// t is about the eye distance, so it is known only to its ulp (1.2e-7 at 1e9), while a
// floor of 1e-10 of the scene radius is 5e-10. Edge neighbours then "overlapped" by one
// ulp and the exact order was blamed on the input (36 pairs at 1e9). The segment floor and
// the overlap threshold follow t's resolution: no pair, and the exact order passes. The
// eye lies in grid planes (y = 3, z = 3), so many rays graze edges. An eye 1e12 away
// (2e11 radii) is refused: the floor would be 1e-4 of the scene there.
TEST(OracleOverlap, FarEyeGivesNoRoundingOverlaps) {
  const CellMesh m = kuhn_block(6);
  const Scene scene = scene_of(m);
  for (double d : {1e6, 1e9, 1e12}) {
    for (bool ortho : {false, true}) {
      Camera cam = test_camera({d, 3, 3}, {3, 3, 3}, 256, 256, ortho, 10.0);
      cam.fov_deg = 2 * std::atan(5.0 / d) * 180 / 3.14159265358979323846;
      const std::vector<int32_t> order = tet_block_exact_order(m, 6, cam);
      if (d > 1e10) {
        EXPECT_THROW(check_ordering(scene, cam, order), InputError);
        continue;
      }
      const OracleResult r = check_ordering(scene, cam, order);
      EXPECT_EQ(r.overlapping_pairs, 0) << "d " << d << " ortho " << ortho << " " << r.overlap_examples.dump();
      EXPECT_EQ(r.violating_fragments, 0) << "d " << d << " ortho " << ortho << " " << r.examples.dump();
      EXPECT_GT(r.covered_pixels, 256 * 256 / 4) << "d " << d << " ortho " << ortho;
    }
  }
}
