// Rays lying exactly in face planes: the edge-on hard case samples an axis-aligned tet
// block on its grid lines in orthographic views along the axes. Every such ray runs along
// faces; the oracle must attribute it to the cells on one side of each plane, consistently,
// or an exact order (MPVO on a convex block) would show violations made by rounding.
#include <gtest/gtest.h>

#include "harness/bench/runner.h"
#include "harness/raster/cell_clip.h"

using namespace vob;

TEST(DegenerateRays, MpvoIsExactOnTheEdgeOnViews) {
  DatasetSpec spec;
  spec.name = "edge-on";
  const Scene scene = make_scene(spec);
  PreparedOrderer p = prepare_orderer("mpvo", scene);
  const auto views = dataset_views(spec, scene, 1, {}, 256, 256, false, 1.0);
  ASSERT_GE(views.size(), 3u);
  for (const auto& [vi, cam] : views) {
    const FrameMeasurement m = measure_frame(p, cam, 0, 1);
    const OracleResult r = check_ordering(scene, cam, m.ordering.order);
    EXPECT_GT(r.covered_pixels, 1000) << "view " << vi;
    EXPECT_EQ(r.violating_fragments, 0) << "view " << vi << " " << r.examples.dump();
  }
}

TEST(DegenerateRays, ARayInASharedFacePlaneBelongsToExactlyOneCell) {
  // Two unit cubes side by side, x in [0,1] and [1,2]; an orthographic view along z whose
  // sample column sits exactly on x = 1, the shared face's plane.
  CellMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) m.points.push_back({double(i), double(j), double(k)});
  auto id = [](int i, int j, int k) { return int32_t(i + 3 * (j + 2 * k)); };
  for (int c = 0; c < 2; ++c)
    m.add_cell(CellType::Hexahedron, {id(c, 0, 0), id(c + 1, 0, 0), id(c + 1, 1, 0), id(c, 1, 0),
                                      id(c, 0, 1), id(c + 1, 0, 1), id(c + 1, 1, 1), id(c, 1, 1)});
  validate_cell_mesh(m, "cubes");
  Camera cam;
  cam.ortho = true;
  cam.width = cam.height = 8;
  cam.ortho_height = 4;  // half a unit per pixel: sample x = 1 + (i + 0.5 - 4) / 2
  cam.eye = {1.25, 0.5, 5};
  cam.target = {1.25, 0.5, 0};
  cam.up = {0, 1, 0};
  const SampleFrame frame(cam, 1);
  const ProjectedPoints proj = project_points(frame, m.points);
  CellClipper clip(frame, m, proj, 1e-12);
  std::vector<int> hits(frame.num_samples(), 0);
  for (int32_t c = 0; c < 2; ++c) {
    clip.setup(c);
    clip.scan(frame.bounds(), [&](int sx, int sy, double, double) { ++hits[frame.index(sx, sy)]; });
  }
  // Sample column 3 has x = 1.25 - 0.25 = 1.0 exactly: on the shared plane.
  ASSERT_EQ(frame.ray(3, 4).origin.x, 1.0);
  EXPECT_EQ(hits[frame.index(3, 4)], 1);
  EXPECT_EQ(hits[frame.index(2, 4)], 1);  // x = 0.5, inside the first cube only
}
