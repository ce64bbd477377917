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

// Polygons are fan-split from their first point: an L-shape fanned from its reflex corner's
// wrong side covered ground outside it, silently, in every surface format: refused. A warped
// convex quad is read as its fan and counted for the reader's note; a planar convex polygon
// whose points carry float rounding reads without one.
TEST(DatasetIO, PolygonsAreFanSplitOnlyInsideThemselves) {
  TempDir dir;
  const std::string l_points[] = {"0 0 0", "2 0 0", "2 1 0", "1 1 0", "1 2 0", "0 2 0"};
  const auto write_all = [&](const std::string& stem, const std::vector<std::string>& pts, const std::vector<int>& face) {
    std::string off = "OFF\n" + std::to_string(pts.size()) + " 1 0\n", obj, ply;
    ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(pts.size()) +
          "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n";
    for (const std::string& p : pts) {  // appended: GCC 12 warns (-Wrestrict) on "v " + p
      off.append(p).append("\n");
      obj.append("v ").append(p).append("\n");
      ply.append(p).append("\n");
    }
    off += std::to_string(face.size()), obj += "f", ply += std::to_string(face.size());
    for (int i : face) {
      off.append(" ").append(std::to_string(i));
      obj.append(" ").append(std::to_string(i + 1));
      ply.append(" ").append(std::to_string(i));
    }
    write_text(dir.file(stem + ".off"), off + "\n");
    write_text(dir.file(stem + ".obj"), obj + "\n");
    write_text(dir.file(stem + ".ply"), ply + "\n");
  };
  const std::vector<std::string> L(std::begin(l_points), std::end(l_points));
  write_all("concave", L, {2, 3, 4, 5, 0, 1});  // fanned from (2,1,0): triangle (2,3,4) lies outside
  write_all("convex_start", L, {3, 4, 5, 0, 1, 2});  // the same L fanned from its reflex corner: inside
  write_all("warped", {"0 0 0", "1 0 0", "1 1 1", "0 1 0"}, {0, 1, 2, 3});
  write_all("tilted", {"0.1234567 0.7654321 0.3333333", "1.2345678 0.1111111 1.4444444", "1.6666667 1.5555556 2.0555556",
                       "0.5555556 2.2098766 0.9444444"}, {0, 1, 2, 3});  // a parallelogram, rounded to 7 digits
  for (const char* ext : {".off", ".obj", ".ply"}) {
    std::string e = input_error([&] { load_input(dir.file(std::string("concave") + ext)); });
    EXPECT_TRUE(contains(e, "polygon of 6 points is not convex: its fan triangle (corners 0, 1, 2: points 2, 3, 4) "
                            "faces against the polygon")) << e;
    EXPECT_TRUE(contains(e, std::string("concave") + ext + ": face 0")) << e;
    // A warped convex quad is split as its fan (one of its two splits), and counted for the note.
    const Scene warped = load_input(dir.file(std::string("warped") + ext));
    EXPECT_EQ(warped.soup().tris.size(), 2u) << ext;
    EXPECT_EQ(warped.soup().warped_polygons, 1u) << ext;
    EXPECT_NEAR(warped.soup().worst_warp, 0.204 / std::sqrt(3.0), 1e-3) << ext;
    EXPECT_EQ(load_input(dir.file(std::string("convex_start") + ext)).soup().tris.size(), 4u) << ext;
    EXPECT_EQ(load_input(dir.file(std::string("tilted") + ext)).soup().tris.size(), 2u) << ext;
  }
}

// Whether a fan triangle faces with the polygon is decided exactly: a quad whose point 1 lies
// within rounding of the diagonal (0, 2) was judged in doubles either way, a concave one
// (point 1 a hair inside the diagonal) fanned outside itself and a convex one refused.
TEST(DatasetIO, PolygonConvexityIsDecidedExactly) {
  TempDir dir;
  const auto quad = [&](const char* name, const char* pts) {
    write_text(dir.file(name), std::string("OFF\n4 1 0\n") + pts + "4 0 1 2 3\n");
    return dir.file(name);
  };
  // Exactly (rationals): triangle (0, 1, 2) faces against the polygon; in doubles it faced with it.
  const std::string e = input_error([&] {
    load_input(quad("concave.off",
                    "0.29607267308315155 0.4997999222368016 0\n1.2220872083243697 1.7339979922452624 0\n"
                    "1.3253456548759963 1.8716215074235552 0\n2.9740994358560524 0.7827003757293756 0\n"));
  });
  EXPECT_TRUE(contains(e, "concave.off: face 0 (line 7): polygon of 4 points is not convex: its fan triangle "
                          "(corners 0, 1, 2: points 0, 1, 2) faces against the polygon"))
      << e;
  // Exactly: both triangles face with the polygon; in doubles (0, 1, 2) faced against it.
  const Scene convex = load_input(quad("convex.off",
                                       "0.6630161884986934 0.38970192767534384 0\n1.284118264496736 1.403366465747911 0\n"
                                       "1.6310630237160113 1.9695948083687032 0\n0.24309173409213014 1.1203681914199144 0\n"));
  EXPECT_EQ(convex.soup().tris.size(), 2u);
}
