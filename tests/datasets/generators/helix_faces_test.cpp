// The helix's `faces` target (Cook et al. Table 1's n and b): counts met, mesh valid.
#include "datasets/generators/helix.h"
#include "harness/scene/cell_mesh.h"
#include "harness/scene/mesh_faces.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

TEST(HelixFaces, TheTableOneHelicesMeetTheirCellsAndFacesWithinFivePercent) {
  // Cook et al. Table 1 (n, b), without building them.
  const int kTable1[][2] = {{450000, 29000},   {1003520, 41472}, {1485000, 59500},
                            {2370000, 67400},  {3570000, 91400}, {4500000, 160000}};
  for (const auto& nb : kTable1) {
    const HelixResolution r = helix_resolution_for_faces(nb[0], nb[1], 3);
    EXPECT_NEAR(double(r.cells()), nb[0], 0.05 * nb[0]) << nb[0];
    EXPECT_NEAR(double(helix_exterior_faces(r)), nb[1], 0.05 * nb[1]) << nb[0];
    EXPECT_GE(r.steps, 18);
    EXPECT_GE(r.inner_rings, 1);
    EXPECT_GE(r.outer_layers, 1);
  }
}

TEST(HelixFaces, TheCountedExteriorFacesAreTheMeshes) {
  // The formula against the faces the scene finds, with and without a target.
  for (auto kv : std::vector<std::vector<std::pair<std::string, std::string>>>{
           {{"cells", "6000"}, {"faces", "900"}}, {{"cells", "12000"}, {"faces", "1000"}}, {{"cells", "3000"}}}) {
    const Scene s = make("helix", kv);
    EXPECT_NO_THROW(validate_cell_mesh(s.mesh(), "helix"));  // positive, non-degenerate cells
    const MeshFaces f = build_mesh_faces(s.mesh(), "helix");
    const int cells = std::stoi(kv[0].second);
    const HelixResolution r = kv.size() > 1 ? helix_resolution_for_faces(cells, std::stoi(kv[1].second), 3)
                                            : helix_resolution(cells, 3);
    EXPECT_EQ(int64_t(s.mesh().num_cells()), r.cells());
    EXPECT_EQ(int64_t(f.boundary.size()), helix_exterior_faces(r));
    if (kv.size() > 1) {
      EXPECT_NEAR(double(f.boundary.size()), std::stod(kv[1].second), 0.05 * std::stod(kv[1].second));
    }
  }
}

TEST(HelixFaces, AnUnreachableTargetIsRefused) {
  // 500 cells cannot have 5000 exterior faces (each cell has at most 4).
  const std::string e = input_error([] { make("helix", {{"cells", "500"}, {"faces", "5000"}}); });
  EXPECT_TRUE(contains(e, "helix: parameter faces")) << e;
}
