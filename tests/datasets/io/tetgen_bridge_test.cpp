// Closed surfaces meshed with TetGen (--tetrahedralize): the mesh, its switches, and the
// surfaces it cannot mesh.
#include <cstdio>
#include <sstream>

#include "datasets/io/tetgen_bridge.h"
#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
// A unit cube surface (12 triangles, outward).
const char* kCube =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
    "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
}  // namespace

TEST(DatasetIO, TetrahedralizeAClosedOff) {
  TempDir dir;
  write_text(dir.file("cube.off"), kCube);
  InputOptions opt;
  opt.tetrahedralize = true;
  const Scene s = load_input(dir.file("cube.off"), opt);
  EXPECT_EQ(s.kind(), SceneKind::Cells);
  EXPECT_GE(s.mesh().num_cells(), 5u);
  double vol = 0;
  for (size_t c = 0; c < s.mesh().num_cells(); ++c) {
    const int32_t* p = s.mesh().cell_points(c);
    const Vec3 a = s.mesh().points[p[0]];
    vol += dot(cross(s.mesh().points[p[1]] - a, s.mesh().points[p[2]] - a), s.mesh().points[p[3]] - a) / 6;
  }
  EXPECT_NEAR(vol, 1.0, 1e-12);
  opt.tetgen_switches = "pq1.2a0.01";
  EXPECT_GT(load_input(dir.file("cube.off"), opt).mesh().num_cells(), 100u);
  opt.tetgen_switches = "q1.2";
  EXPECT_TRUE(contains(input_error([&] { load_input(dir.file("cube.off"), opt); }), "need 'p'"));
  opt.tetgen_switches = "p;rm";
  EXPECT_TRUE(contains(input_error([&] { load_input(dir.file("cube.off"), opt); }), "is not a switch"));
}

TEST(DatasetIO, TetgenOnAnOpenSurface) {
  TempDir dir;
  std::string open = kCube;
  open.replace(open.find("12 0"), 4, "10 0");  // drop the last two triangles (one side)
  open = open.substr(0, open.rfind("3 3 0 4"));
  write_text(dir.file("open.off"), open);
  InputOptions opt;
  opt.tetrahedralize = true;
  const std::string e = input_error([&] { load_input(dir.file("open.off"), opt); });
  EXPECT_TRUE(contains(e, "open.off: edge (0,3): belongs to 1 triangle: the surface is not closed")) << e;
  // TetGen itself, given the open surface, silently makes no tetrahedra: also an error.
  const TriangleSoup soup = load_input(dir.file("open.off")).soup();
  const std::string e2 = input_error([&] { tetrahedralize_surface(soup, "open.off", ""); });
  EXPECT_TRUE(contains(e2, "open.off: surface: tetgen produced no tetrahedra")) << e2;
  std::printf("%s\n%s\n", e.c_str(), e2.c_str());
}

TEST(DatasetIO, TetgenOnASelfIntersectingSurface) {
  TempDir dir;
  // Two closed cubes that interpenetrate: every edge has two triangles, yet faces cross.
  std::string two = "OFF\n16 24 0\n";
  for (double o : {0.0, 0.5})
    for (const char* v : {"0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1"}) {
      double x, y, z;
      std::sscanf(v, "%lf %lf %lf", &x, &y, &z);
      two += std::to_string(x + o) + " " + std::to_string(y + o * 0.7) + " " + std::to_string(z + o * 0.3) + "\n";
    }
  const std::string faces = std::string(kCube).substr(std::string(kCube).find("3 0 2 1"));
  two += faces;
  std::istringstream in(faces);
  std::string line;
  while (std::getline(in, line)) {
    int n, a, b, c;
    std::sscanf(line.c_str(), "%d %d %d %d", &n, &a, &b, &c);
    two += "3 " + std::to_string(a + 8) + " " + std::to_string(b + 8) + " " + std::to_string(c + 8) + "\n";
  }
  write_text(dir.file("two.off"), two);
  InputOptions opt;
  opt.tetrahedralize = true;
  const std::string e = input_error([&] { load_input(dir.file("two.off"), opt); });
  EXPECT_TRUE(contains(e, "two.off: tetgen facets #")) << e;
  EXPECT_TRUE(contains(e, "the surface intersects itself")) << e;
  std::printf("%s\n", e.c_str());
}

TEST(DatasetIO, TetgenSwitchesReachTheMesh) {
  TempDir dir;
  write_text(dir.file("cube.off"), kCube);
  InputOptions opt;
  opt.tetrahedralize = true;
  opt.tetgen_switches = "-o2";  // no p
  EXPECT_TRUE(contains(input_error([&] { load_input(dir.file("cube.off"), opt); }), "need 'p'"));
  opt.tetgen_switches = "po2";  // second-order output
  EXPECT_TRUE(contains(input_error([&] { load_input(dir.file("cube.off"), opt); }),
                       "cube.off: tetgen switches 'po2': 'o' is not allowed"));
}

// Closed surfaces around no volume: TetGen 1.5 aborted on each (`Assertion 'maxz > 0'` for the
// flat one in z = 0, SIGSEGV for a doubled triangle, a bogus self-intersection for the tilted
// one); they are refused before it runs.
TEST(DatasetIO, TetgenIsNotGivenSurfacesAroundNoVolume) {
  TempDir dir;
  InputOptions opt;
  opt.tetrahedralize = true;
  const auto refused = [&](const char* name, const std::string& text) {
    write_text(dir.file(name), text);
    const std::string e = input_error([&] { load_input(dir.file(name), opt); });
    std::printf("%s\n", e.c_str());
    return e;
  };
  const char* flat_faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  std::string e = refused("flat.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0.2 0.2 0\n") + flat_faces);
  EXPECT_TRUE(contains(e, "flat.off: surface: all its points lie in one plane: it encloses no volume")) << e;
  e = refused("tilted.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 1\n0 1 1\n0.2 0.2 0.4\n") + flat_faces);
  EXPECT_TRUE(contains(e, "tilted.off: surface: all its points lie in one plane")) << e;
  e = refused("double.off", "OFF\n3 2 0\n0 0 0\n1 0 1\n0 1 1\n3 0 1 2\n3 0 2 1\n");
  EXPECT_TRUE(contains(e, "double.off: triangles 0 and 1: have the same three points")) << e;
  // A cube beside a flat piece: the piece is named by its first triangle.
  std::string cube_and_flat = kCube;
  cube_and_flat.replace(cube_and_flat.find("8 12 0"), 6, "12 16 0");
  const size_t faces_at = cube_and_flat.find("3 0 2 1");
  cube_and_flat.insert(faces_at, "5 5 5\n6 5 5\n5 6 5\n5.2 5.2 5\n");
  cube_and_flat += "3 8 10 9\n3 8 9 11\n3 8 11 10\n3 9 10 11\n";
  e = refused("cube_and_flat.off", cube_and_flat);
  EXPECT_TRUE(contains(e, "cube_and_flat.off: the piece with triangle 12: all its points lie in one plane")) << e;
  // The cube alone still meshes.
  write_text(dir.file("cube.off"), kCube);
  EXPECT_GE(load_input(dir.file("cube.off"), opt).mesh().num_cells(), 5u);
}
