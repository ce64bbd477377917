// OFF surfaces: errors naming the line and element, polygons fan-split.
#include <cmath>

#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

TEST(DatasetIO, NanCoordinateInVtuAndOff) {
  TempDir dir;
  CellMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}, {0, 0, 1}};
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  write_scene(Scene::from_mesh("nan", m), dir.file("nan.vtu"));
  std::string e = input_error([&] { load_input(dir.file("nan.vtu")); });
  EXPECT_TRUE(contains(e, "nan.vtu: point 2: coordinate is not finite")) << e;
  write_text(dir.file("nan.off"), "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  e = input_error([&] { load_input(dir.file("nan.off")); });
  EXPECT_TRUE(contains(e, "nan.off: vertex 1 (line 4): value 'nan' is not finite")) << e;
}

TEST(DatasetIO, OffErrors) {
  TempDir dir;
  write_text(dir.file("a.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  std::string e = input_error([&] { load_input(dir.file("a.off")); });
  EXPECT_TRUE(contains(e, "a.off: face 0 (line 6): vertex index 3 is out of range [0, 2]")) << e;
  write_text(dir.file("b.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n");
  e = input_error([&] { load_input(dir.file("b.off")); });
  EXPECT_TRUE(contains(e, "b.off: vertex 3: file ends early")) << e;
  write_text(dir.file("c.off"), "PLY\n");
  e = input_error([&] { load_input(dir.file("c.off")); });
  EXPECT_TRUE(contains(e, "c.off: header (line 1): 'PLY' is not an OFF header")) << e;
  write_text(dir.file("d.off"), "OFF 3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
  e = input_error([&] { load_input(dir.file("d.off")); });
  EXPECT_TRUE(contains(e, "d.off: triangle 0: has zero area")) << e;
  // Polygons are fan-split; colours after the indices are ignored.
  write_text(dir.file("q.off"), "COFF\n# quad\n4 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n1 1 0 1 1 1 1\n0 1 0 1 1 1 1\n4 0 1 2 3 255 0 0\n");
  EXPECT_EQ(load_input(dir.file("q.off")).soup().tris,
            (std::vector<std::array<int32_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
}
