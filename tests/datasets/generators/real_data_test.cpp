// Real data from the libcgal-demo archive: extraction into the cache, the CT skull, the
// surfaces and their TetGen meshes (slow the first time: TetGen runs, then it is cached).
#include <chrono>
#include <cstdio>

#include "harness/scene/mesh_faces.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

TEST(RealData, Skull) {
  const Scene s = make("skull");
  EXPECT_EQ(s.grid().dims, (std::array<int32_t, 3>{64, 64, 64}));
  EXPECT_NEAR(s.grid().spacing.x, 3.94305, 1e-5);
  EXPECT_NO_THROW(validate_voxel_grid(s.grid(), "skull"));
  const double frac = double(s.num_primitives()) / s.grid().num_voxels();
  EXPECT_GT(frac, 0.1);
  EXPECT_LT(frac, 0.5);
}

TEST(RealData, SurfacesAndTetMeshes) {
  for (const auto& info : dataset_registry()) {
    const bool surf = info.name.rfind("surface-", 0) == 0, tet = info.name.rfind("tet-", 0) == 0;
    if (!surf && !tet) continue;
    SCOPED_TRACE(info.name);
    const auto t0 = std::chrono::steady_clock::now();
    const Scene s = make(info.name);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (surf) {
      EXPECT_NO_THROW(validate_triangle_soup(s.soup(), info.name));
      std::printf("%-22s %8zu triangles %7.2f s\n", info.name.c_str(), s.soup().num_triangles(), sec);
    } else {
      EXPECT_NO_THROW(validate_cell_mesh(s.mesh(), info.name));
      const MeshFaces f = build_mesh_faces(s.mesh(), info.name);
      EXPECT_GT(s.mesh().num_cells(), 10000u);
      EXPECT_EQ(s.mesh().scalars.size(), s.mesh().num_points());
      std::printf("%-22s %8zu tets %7zu boundary faces %7.2f s\n", info.name.c_str(),
                  s.mesh().num_cells(), f.boundary.size(), sec);
    }
  }
}

TEST(RealData, TetMeshesAreCachedPerSwitches) {
  const Scene a = make("tet-hand");
  const auto t0 = std::chrono::steady_clock::now();
  const Scene b = make("tet-hand");
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(a.mesh().conn, b.mesh().conn);
  EXPECT_LT(sec, 2.0);
  const Scene c = make("tet-hand", {{"maxvol", "0.0001"}});
  EXPECT_GT(c.mesh().num_cells(), a.mesh().num_cells());
  EXPECT_EQ(c.params()["tetgen"].get<std::string>().substr(0, 10), "pq1.414a0.");
}
