// Readers and writers: exact round trips, and bad input as one InputError line that names
// the file, the element and the reason.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "datasets/io/inr_reader.h"
#include "datasets/io/tetgen_bridge.h"
#include "datasets/io/vtk_io.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

void expect_same(const CellMesh& a, const CellMesh& b) {
  EXPECT_TRUE(a.points == b.points);
  EXPECT_EQ(a.scalars, b.scalars);
  EXPECT_EQ(a.types, b.types);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.conn, b.conn);
}

// A unit cube surface (12 triangles, outward).
const char* kCube =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
    "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";

const char* kTwoTetsNode = "# two tetrahedra sharing a face\n5 3 1 0\n1 0 0 0 0.5\n2 1 0 0 1\n3 0 1 0 2\n4 0 0 1 3\n5 1 1 1 4\n";
const char* kTwoTetsEle = "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n";
}  // namespace

TEST(DatasetIO, CellRoundTripsAreExact) {
  TempDir dir;
  for (const char* name : {"zoo", "gap", "helix"}) {
    const Scene s = name == std::string("gap") ? make(name, {{"nx", "3"}, {"ny", "2"}, {"nz", "4"}, {"gaps", "1"}})
                                               : make(name, {{name == std::string("helix") ? "cells" : "scale",
                                                              name == std::string("helix") ? "2000" : "1"}});
    for (const char* ext : {".vtu", ".vtk"}) {
      SCOPED_TRACE(std::string(name) + ext);
      const std::string path = dir.file(std::string(name) + ext);
      write_scene(s, path);
      expect_same(s.mesh(), load_input(path).mesh());
    }
  }
  const Scene tets = make("helix", {{"cells", "1000"}});
  write_scene(tets, dir.file("h.node"));
  expect_same(tets.mesh(), load_input(dir.file("h.node")).mesh());
  expect_same(tets.mesh(), load_input(dir.file("h.ele")).mesh());  // either file names the pair
}

TEST(DatasetIO, VoxelAndTriangleRoundTripsAreExact) {
  TempDir dir;
  const Scene v = make("sparse", {{"nx", "20"}, {"ny", "12"}, {"nz", "9"}});
  write_scene(v, dir.file("v.vti"));
  const Scene v2 = load_input(dir.file("v.vti"));
  EXPECT_EQ(v.grid().dims, v2.grid().dims);
  EXPECT_EQ(v.grid().values, v2.grid().values);
  EXPECT_TRUE(v.grid().origin == v2.grid().origin);
  EXPECT_TRUE(v.grid().spacing == v2.grid().spacing);
  EXPECT_EQ(v.grid().threshold, v2.grid().threshold);
  const Scene t = make("spheres", {{"subdiv", "1"}});
  write_scene(t, dir.file("t.off"));
  const Scene t2 = load_input(dir.file("t.off"));
  EXPECT_TRUE(t.soup().points == t2.soup().points);
  EXPECT_EQ(t.soup().tris, t2.soup().tris);
}

TEST(DatasetIO, WriteRefusesTheWrongExtensionAndLeavesNoTemporaryFiles) {
  TempDir dir;
  const std::string e = input_error([&] { write_scene(make("sphere"), dir.file("s.vtu")); });
  EXPECT_TRUE(contains(e, "s.vtu: file: a triangles scene is written as .off")) << e;
  write_scene(make("cycle"), dir.file("sub/c.vtu"));
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("sub")))
    files.push_back(entry.path().filename().string());
  EXPECT_EQ(files, std::vector<std::string>{"c.vtu"});
  EXPECT_TRUE(contains(input_error([&] { write_scene(make("zoo"), dir.file("z.node")); }),
                       "is a pyramid; TetGen files hold tetrahedra only"));
}

TEST(DatasetIO, LegacyStructuredPointsAreVoxels) {
  TempDir dir;
  write_text(dir.file("sp.vtk"),
             "# vtk DataFile Version 3.0\nvol\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 1\n"
             "SPACING 1 2 3\nORIGIN 0.5 0 0\nPOINT_DATA 6\nSCALARS v float 1\nLOOKUP_TABLE default\n"
             "0 1 2 3 4 5\n");
  const Scene s = load_input(dir.file("sp.vtk"));
  ASSERT_EQ(s.kind(), SceneKind::Voxels);
  EXPECT_EQ(s.grid().dims, (std::array<int32_t, 3>{3, 2, 1}));
  EXPECT_EQ(s.grid().values, (std::vector<float>{0, 1, 2, 3, 4, 5}));
  EXPECT_TRUE(s.grid().spacing == Vec3(1, 2, 3));
  EXPECT_TRUE(s.grid().origin == Vec3(0.5, 0, 0));
  EXPECT_EQ(s.num_primitives(), 5u);  // threshold 0: values > 0
}

TEST(DatasetIO, TetgenFilesWithOneBasedIndicesCommentsAndAttributes) {
  TempDir dir;
  write_text(dir.file("t.node"), kTwoTetsNode);
  write_text(dir.file("t.ele"), kTwoTetsEle);
  const Scene s = load_input(dir.file("t.node"));
  ASSERT_EQ(s.mesh().num_cells(), 2u);
  EXPECT_EQ(s.mesh().conn, (std::vector<int32_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(s.mesh().scalars, (std::vector<double>{0.5, 1, 2, 3, 4}));
}

TEST(DatasetIO, TruncatedOrMalformedTetgenFiles) {
  TempDir dir;
  write_text(dir.file("a.node"), "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n");
  write_text(dir.file("a.ele"), "1 4 0\n0 0 1 2 3\n");
  std::string e = input_error([&] { load_input(dir.file("a.node")); });
  EXPECT_TRUE(contains(e, "a.node: point 3: file ends early: the header promises 5 points, found 3")) << e;

  write_text(dir.file("b.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  write_text(dir.file("b.ele"), "2 4 0\n0 0 1 2 3\n");
  e = input_error([&] { load_input(dir.file("b.node")); });
  EXPECT_TRUE(contains(e, "b.ele: tetrahedron 1: file ends early")) << e;

  write_text(dir.file("c.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1\n3 0 0 1\n");
  write_text(dir.file("c.ele"), "1 4 0\n0 0 1 2 3\n");
  e = input_error([&] { load_input(dir.file("c.node")); });
  EXPECT_TRUE(contains(e, "c.node: point 2 (line 4): expected 4 values")) << e;

  write_text(dir.file("d.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  write_text(dir.file("d.ele"), "1 4 0\n0 0 1 2 4\n");
  e = input_error([&] { load_input(dir.file("d.node")); });
  EXPECT_TRUE(contains(e, "d.ele: tetrahedron 0 (line 2): point index 4 is out of range [0, 3]")) << e;

  write_text(dir.file("e.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 nan 0\n3 0 0 1\n");
  write_text(dir.file("e.ele"), "1 4 0\n0 0 1 2 3\n");
  e = input_error([&] { load_input(dir.file("e.node")); });
  EXPECT_TRUE(contains(e, "e.node: point 2 (line 4): value 'nan' is not finite")) << e;

  write_text(dir.file("f.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  write_text(dir.file("f.ele"), "1 4 0\n0 0 2 1 3\n");  // inverted
  e = input_error([&] { load_input(dir.file("f.node")); });
  EXPECT_TRUE(contains(e, "f.node: cell 0: is inverted")) << e;

  write_text(dir.file("g.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  e = input_error([&] { load_input(dir.file("g.node")); });
  EXPECT_TRUE(contains(e, "g.ele: file: does not exist")) << e;

  // A header that promises two billion points must not make the reader allocate them.
  write_text(dir.file("h.node"), "2000000000 3 0 0\n0 0 0 0\n");
  write_text(dir.file("h.ele"), "1 4 0\n0 0 1 2 3\n");
  e = input_error([&] { load_input(dir.file("h.node")); });
  EXPECT_TRUE(contains(e, "h.node: header (line 1): point count 2000000000 cannot fit in a file of")) << e;
}

TEST(DatasetIO, FaceSharedByThreeCellsIsRejected) {
  TempDir dir;
  // Three tetrahedra on face (0,1,2): two above would overlap, so use apexes on both sides
  // and a third above: the face has three owners.
  write_text(dir.file("t.node"), "6 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0.2 0.2 1\n4 0.2 0.2 -1\n5 0.3 0.3 2\n");
  write_text(dir.file("t.ele"), "3 4 0\n0 0 1 2 3\n1 0 2 1 4\n2 0 1 2 5\n");
  const std::string e = input_error([&] { load_input(dir.file("t.node")); });
  EXPECT_TRUE(contains(e, "t.node: face (0,1,2): shared by more than two cells (0, 1, 2)")) << e;
}

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

TEST(DatasetIO, VtkErrors) {
  TempDir dir;
  // A file with a triangle and no volume cell.
  write_text(dir.file("tri.vtk"),
             "# vtk DataFile Version 3.0\ntri\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n"
             "0 0 0 1 0 0 0 1 0\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n");
  std::string e = input_error([&] { load_input(dir.file("tri.vtk")); });
  EXPECT_TRUE(contains(e, "tri.vtk: cells: none of the 1 cells is a volume cell")) << e;
  write_text(dir.file("bad.vtu"), "<VTKFile type=\"UnstructuredGrid\"><Unstr");
  e = input_error([&] { load_input(dir.file("bad.vtu")); });
  EXPECT_TRUE(contains(e, "bad.vtu: XML byte 33: tag is not closed")) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  std::printf("%s\n", e.c_str());
  e = input_error([&] { load_input(dir.file("missing.vtu")); });
  EXPECT_TRUE(contains(e, "missing.vtu: file: does not exist")) << e;
  e = input_error([&] { load_input(dir.file("x.stl")); });
  EXPECT_TRUE(contains(e, "does not exist")) << e;
  write_text(dir.file("x.stl"), "solid\n");  // an ASCII STL without triangles
  e = input_error([&] { load_input(dir.file("x.stl")); });
  EXPECT_TRUE(contains(e, "x.stl: file: VTK: STLReader: error while reading")) << e;
  write_text(dir.file("x.xyz"), "0 0 0\n");
  e = input_error([&] { load_input(dir.file("x.xyz")); });
  EXPECT_TRUE(contains(e, "x.xyz: file: unknown extension '.xyz'")) << e;
}

// What VTK's PLY reader takes from the header unchecked (it crashed or misread without the
// prescan's checks), and the count types it converts.
TEST(DatasetIO, PlyHeaderAsVtkReadsIt) {
  TempDir dir;
  const std::string vertices = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const auto ascii = [&](const std::string& name, const std::string& header, const std::string& body) {
    write_text(dir.file(name), "ply\nformat ascii 1.0\n" + header + "end_header\n" + body);
    return dir.file(name);
  };
  // The faces' list by its other name, read as the usual one.
  const std::string other = ascii("other.ply", vertices + "element face 4\nproperty list uchar int vertex_index\n", points + faces);
  EXPECT_EQ(load_input(other).soup().tris.size(), 4u);
  // ... and range-checked like it.
  std::string e = input_error([&] {
    load_input(ascii("far.ply", vertices + "element face 1\nproperty list uchar int vertex_index\n", points + "3 0 1 7\n"));
  });
  EXPECT_TRUE(contains(e, "far.ply: face 0: vertex index 7 is out of range (4 vertices)")) << e;
  e = input_error([&] {
    load_input(ascii("nolist.ply", vertices + "element face 4\nproperty list uchar int verts\n", points + faces));
  });
  EXPECT_TRUE(contains(e, "nolist.ply: element face: no list property 'vertex_indices' or 'vertex_index'")) << e;
  e = input_error([&] {
    load_input(ascii("scalar.ply", vertices + "element face 4\nproperty int vertex_indices\n", points + "0\n1\n2\n3\n"));
  });
  EXPECT_TRUE(contains(e, "scalar.ply: element face: no list property")) << e;
  e = input_error([&] {
    load_input(ascii("nox.ply", "element vertex 4\nproperty float w\nproperty float y\nproperty float z\n"
                                "element face 4\nproperty list uchar int vertex_indices\n", points + faces));
  });
  EXPECT_TRUE(contains(e, "nox.ply: element vertex: no scalar property 'x'")) << e;
  e = input_error([&] {
    load_input(ascii("first.ply", "element face 4\nproperty list uchar int vertex_indices\n" + vertices, faces + points));
  });
  EXPECT_TRUE(contains(e, "first.ply: element face: comes before element vertex")) << e;
  // VTK keeps a polygon's count in a byte: 300 points would be read as 44.
  std::string ring = "300";
  for (int i = 0; i < 300; ++i) ring += " " + std::to_string(i % 4);
  e = input_error([&] {
    load_input(ascii("ring.ply", vertices + "element face 1\nproperty list ushort int vertex_indices\n", points + ring + "\n"));
  });
  EXPECT_TRUE(contains(e, "ring.ply: face 0: polygon of 300 points")) << e;
  // Binary list counts of every width and kind, as VTK converts them (an 8-byte count once
  // overran the prescan's 4-byte buffer).
  const auto binary = [&](const std::string& name, const std::string& count_type, const std::string& count_bytes) {
    std::string body;
    const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    body.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const int32_t tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    for (const auto& t : tris) body += count_bytes + std::string(reinterpret_cast<const char*>(t), sizeof t);
    write_text(dir.file(name), "ply\nformat binary_little_endian 1.0\n" + vertices + "element face 4\nproperty list " +
                                   count_type + " int vertex_indices\nend_header\n" + body);
    return dir.file(name);
  };
  const auto bytes_of = [](auto v) { return std::string(reinterpret_cast<const char*>(&v), sizeof v); };
  EXPECT_EQ(load_input(binary("d.ply", "double", bytes_of(3.0))).soup().tris.size(), 4u);
  EXPECT_EQ(load_input(binary("f.ply", "float", bytes_of(3.0f))).soup().tris.size(), 4u);
  EXPECT_EQ(load_input(binary("s.ply", "short", bytes_of(int16_t(3)))).soup().tris.size(), 4u);
  e = input_error([&] { load_input(binary("half.ply", "float", bytes_of(2.5f))); });
  EXPECT_TRUE(contains(e, "half.ply: face 0: list count 2.5 is not a valid count")) << e;
  e = input_error([&] { load_input(binary("neg.ply", "char", bytes_of(int8_t(-3)))); });
  EXPECT_TRUE(contains(e, "neg.ply: face 0: list count -3 is not a valid count")) << e;
}

TEST(DatasetIO, InrHeaderTypesAndEndianness) {
  TempDir dir;
  auto inr = [&](const std::string& name, const std::string& fields, const std::string& data) {
    std::string h = "#INRIMAGE-4#{\n" + fields;
    h += std::string(252 - h.size(), '\n') + "##}\n";
    write_text(dir.file(name), h + data);
  };
  inr("u16.inr", "XDIM=2\nYDIM=1\nZDIM=1\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=16 bits\nCPU=sun\nVX=2\n",
      std::string("\x01\x02\x00\x05", 4));
  const VoxelGrid g = load_input(dir.file("u16.inr")).grid();
  EXPECT_EQ(g.values, (std::vector<float>{258, 5}));
  EXPECT_EQ(g.spacing.x, 2.0);
  float f[2] = {1.5f, -2.0f};
  inr("f.inr", "XDIM=1\nYDIM=2\nZDIM=1\nTYPE=float\nPIXSIZE=32 bits\nCPU=decm\n", std::string(reinterpret_cast<char*>(f), 8));
  EXPECT_EQ(load_input(dir.file("f.inr")).grid().values, (std::vector<float>{1.5f, -2.0f}));
  inr("short.inr", "XDIM=4\nYDIM=4\nZDIM=4\nTYPE=float\nPIXSIZE=32 bits\nCPU=decm\n", std::string(20, '\0'));
  std::string e = input_error([&] { load_input(dir.file("short.inr")); });
  EXPECT_TRUE(contains(e, "short.inr: voxel 5: file ends early")) << e;
  inr("huge.inr", "XDIM=1200\nYDIM=1200\nZDIM=1200\nTYPE=float\nPIXSIZE=64 bits\nCPU=decm\n", std::string(64, '\0'));
  e = input_error([&] { load_input(dir.file("huge.inr")); });
  EXPECT_TRUE(contains(e, "huge.inr: voxel 8: file ends early")) << e;
  inr("vdim.inr", "XDIM=1\nYDIM=1\nZDIM=1\nVDIM=3\nTYPE=float\nPIXSIZE=32 bits\n", std::string(12, '\0'));
  e = input_error([&] { load_input(dir.file("vdim.inr")); });
  EXPECT_TRUE(contains(e, "vdim.inr: header VDIM: vector images")) << e;
  write_text(dir.file("no.inr"), std::string(300, 'x'));
  e = input_error([&] { load_input(dir.file("no.inr")); });
  EXPECT_TRUE(contains(e, "no.inr: header: does not start with #INRIMAGE-4#{")) << e;
}

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

namespace {
// A cube hexahedron with point scalars, plus what gmsh writes beside volume cells: a
// vertex, a line and a triangle; `types` replaces the hexahedron's type.
std::string gmsh_like_vtk(int hex_type = 12) {
  return "# vtk DataFile Version 2.0\ncube, Created by Gmsh\nASCII\nDATASET UNSTRUCTURED_GRID\n"
         "POINTS 9 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n0.5 0.5 0.5\n"
         "CELLS 4 18\n1 8\n2 0 1\n3 0 1 2\n8 0 1 2 3 4 5 6 7\n"
         "CELL_TYPES 4\n1\n3\n5\n" + std::to_string(hex_type) +
         "\nPOINT_DATA 9\nSCALARS s double 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7 8\n";
}
}  // namespace

TEST(DatasetIO, LowerDimensionalCellsBesideVolumeCellsAreSkippedAndNoted) {
  TempDir dir;
  write_text(dir.file("g.vtk"), gmsh_like_vtk());
  std::string note;
  const Scene s = read_vtk_file(dir.file("g.vtk"), &note);
  ASSERT_EQ(s.mesh().num_cells(), 1u);
  EXPECT_EQ(s.mesh().types[0], CellType::Hexahedron);
  EXPECT_EQ(s.mesh().conn, (std::vector<int32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  // Points keep the file's numbering, so the scalars stay with their points.
  ASSERT_EQ(s.mesh().num_points(), 9u);
  EXPECT_EQ(s.mesh().scalars[5], 5.0);
  EXPECT_EQ(note, "read the volume cells only; skipped 3 cells of lower dimension "
                  "(vtkLine 1, vtkTriangle 1, vtkVertex 1)");
  EXPECT_EQ(load_input(dir.file("g.vtk")).mesh().num_cells(), 1u);
  // Volume cells outside the four are refused by name, not skipped.
  write_text(dir.file("q.vtk"), gmsh_like_vtk(25));
  std::string e = input_error([&] { load_input(dir.file("q.vtk")); });
  EXPECT_TRUE(contains(e, "q.vtk: cell 3: type 25 (vtkQuadraticHexahedron) is not supported")) << e;
  write_text(dir.file("v.vtk"), gmsh_like_vtk(11));
  e = input_error([&] { load_input(dir.file("v.vtk")); });
  EXPECT_TRUE(contains(e, "v.vtk: cell 3: type 11 (vtkVoxel) is not supported")) << e;
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

TEST(DatasetIO, DeclaredSizesBeyondTheFileAreRefusedBeforeReading) {
  TempDir dir;
  std::string text = gmsh_like_vtk();
  text.replace(text.find("POINTS 9"), 8, "POINTS 900000000");
  write_text(dir.file("p.vtk"), text);
  std::string e = input_error([&] { load_input(dir.file("p.vtk")); });
  EXPECT_TRUE(contains(e, "p.vtk: POINTS (line 5): point count 900000000 cannot fit")) << e;
  write_text(dir.file("d.vtu"), "<VTKFile type=\"UnstructuredGrid\">" + repeat("<a>", 20000) + repeat("</a>", 20000) + "</VTKFile>");
  e = input_error([&] { load_input(dir.file("d.vtu")); });
  EXPECT_TRUE(contains(e, "d.vtu: XML byte")) << e;
  write_text(dir.file("o.vti"),
             "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"nan 0 0\" "
             "Spacing=\"1 1 1\"></ImageData></VTKFile>");
  e = input_error([&] { load_input(dir.file("o.vti")); });
  EXPECT_TRUE(contains(e, "o.vti: ImageData Origin: 'nan' is not a finite number")) << e;
}

// VTK reports a short binary read only as a warning; it must still refuse the file.
TEST(DatasetIO, TruncatedBinaryLegacyVtkIsRefused) {
  TempDir dir;
  const Scene zoo = make("zoo");
  write_scene(zoo, dir.file("full.vtk"));
  std::ifstream in(dir.file("full.vtk"), std::ios::binary);
  std::stringstream all;
  all << in.rdbuf();
  const std::string bytes = all.str();
  for (const double keep : {0.3, 0.6, 0.9}) {
    write_text(dir.file("cut.vtk"), bytes.substr(0, static_cast<size_t>(bytes.size() * keep)));
    const std::string e = input_error([&] { load_input(dir.file("cut.vtk")); });
    EXPECT_TRUE(contains(e, "cut.vtk: ")) << keep << ": " << e;
  }
}

// ParaView extracts mix surface cells into .vtu files too.
TEST(DatasetIO, LowerDimensionalCellsInVtuAreSkipped) {
  TempDir dir;
  write_text(dir.file("m.vtu"),
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
             "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"2\"><Points>"
             "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1"
             "</DataArray></Points><Cells>"
             "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 2 1 0 1 2 3</DataArray>"
             "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3 7</DataArray>"
             "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 10</DataArray>"
             "</Cells></Piece></UnstructuredGrid></VTKFile>\n");
  std::string note;
  const Scene s = read_vtk_file(dir.file("m.vtu"), &note);
  EXPECT_EQ(s.mesh().num_cells(), 1u);
  EXPECT_EQ(s.mesh().types[0], CellType::Tetra);
  EXPECT_TRUE(contains(note, "skipped 1 cells of lower dimension (vtkTriangle 1)")) << note;
}

namespace {
// The gmsh reader is a module beside libvobench.so, which this test does not link: .msh
// files are read by the program. The one line it refuses `path` with (exit 2).
std::string msh_error(const std::string& path) {
  const CommandOutput r = run_vobench(VOB_BINARY, "validate " + path);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  return r.out;
}
// The cell count the program reads from a valid `path`.
size_t msh_cells(const std::string& path) {
  const CommandOutput r = run_vobench(VOB_BINARY, "validate " + path);
  EXPECT_EQ(r.code, 0) << r.out;
  return size_t(std::strtoull(r.out.substr(r.out.find(": ") + 2).c_str(), nullptr, 10));
}

// One tetrahedron (or more) in gmsh's MSH 4.1 ASCII format: node tags as given, one per
// point of kTetPoints, and element lines "tag n1 n2 n3 n4".
const char* kTetPoints[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 1 1"};
std::string msh41(const std::vector<std::string>& node_tags, const std::vector<std::string>& elements) {
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n";
  s += "$Nodes\n1 " + std::to_string(node_tags.size()) + " 1 " + node_tags.back() + "\n3 1 0 " +
       std::to_string(node_tags.size()) + "\n";
  for (const std::string& t : node_tags) s += t + "\n";
  for (size_t i = 0; i < node_tags.size(); ++i) s += std::string(kTetPoints[i]) + "\n";
  s += "$EndNodes\n$Elements\n1 " + std::to_string(elements.size()) + " 1 " + std::to_string(elements.size()) +
       "\n3 1 4 " + std::to_string(elements.size()) + "\n";
  for (const std::string& e : elements) s += e + "\n";
  return s + "$EndElements\n";
}
// The same in MSH 2.2 ASCII; element lines "id type ntags tags... nodes...".
std::string msh22(const std::vector<std::string>& node_tags, const std::vector<std::string>& elements) {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(node_tags.size()) + "\n";
  for (size_t i = 0; i < node_tags.size(); ++i) s += node_tags[i] + " " + kTetPoints[i] + "\n";
  s += "$EndNodes\n$Elements\n" + std::to_string(elements.size()) + "\n";
  for (const std::string& e : elements) s += e + "\n";
  return s + "$EndElements\n";
}
}  // namespace

// gmsh 4.8 narrows node and element tags to 32-bit ints on the way: a node tag in
// [2^31, 2^32) (mod 2^32) crashed it (SIGSEGV), 2^32 + 1 became tag 1.
TEST(DatasetIO, GmshTagsBeyond2To31AreRefused) {
  TempDir dir;
  for (const std::string tag : {"3000000000", "1000000000000000", "4294967297"}) {
    SCOPED_TRACE(tag);
    write_text(dir.file("n.msh"), msh41({"1", "2", "3", tag}, {"1 1 2 3 " + tag}));
    std::string e = msh_error(dir.file("n.msh"));
    EXPECT_TRUE(contains(e, "n.msh: $Nodes: block 1: node tag " + tag + " is beyond 2147483647")) << e;
    write_text(dir.file("e.msh"), msh41({"1", "2", "3", "4"}, {tag + " 1 2 3 4"}));
    e = msh_error(dir.file("e.msh"));
    EXPECT_TRUE(contains(e, "e.msh: $Elements: block 1: element tag " + tag + " is beyond 2147483647")) << e;
    write_text(dir.file("n2.msh"), msh22({"1", "2", "3", tag}, {"1 4 2 0 1 1 2 3 " + tag}));
    e = msh_error(dir.file("n2.msh"));
    EXPECT_TRUE(contains(e, "n2.msh: node " + tag + " (line 9): tag is beyond 2147483647")) << e;
    write_text(dir.file("e2.msh"), msh22({"1", "2", "3", "4"}, {tag + " 4 2 0 1 1 2 3 4"}));
    e = msh_error(dir.file("e2.msh"));
    EXPECT_TRUE(contains(e, "e2.msh: element " + tag + " (line 13): tag is beyond 2147483647")) << e;
  }
  // The binary file's tags are the same 8-byte fields.
  std::string bin = "$MeshFormat\n4.1 1 8\n";
  const auto put = [&](auto v) { bin.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(int32_t(1));
  bin += "\n$EndMeshFormat\n$Nodes\n";
  for (const uint64_t v : {1ull, 4ull, 1ull, 3000000000ull}) put(v);
  put(int32_t(3)), put(int32_t(1)), put(int32_t(0)), put(uint64_t(4));
  for (const uint64_t t : {1ull, 2ull, 3ull, 3000000000ull}) put(t);
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) put(double(i == a + 1));
  bin += "\n$EndNodes\n$Elements\n";
  for (const uint64_t v : {1ull, 1ull, 1ull, 1ull}) put(v);
  put(int32_t(3)), put(int32_t(1)), put(int32_t(4)), put(uint64_t(1));
  for (const uint64_t v : {1ull, 1ull, 2ull, 3ull, 3000000000ull}) put(v);
  bin += "\n$EndElements\n";
  write_text(dir.file("b.msh"), bin);
  std::string e = msh_error(dir.file("b.msh"));
  EXPECT_TRUE(contains(e, "b.msh: $Nodes: block 1: node tag 3000000000 is beyond 2147483647")) << e;
  // The largest tag gmsh holds is read.
  write_text(dir.file("max.msh"), msh41({"1", "2", "3", "2147483647"}, {"2147483647 1 2 3 2147483647"}));
  EXPECT_EQ(msh_cells(dir.file("max.msh")), 1u);
  write_text(dir.file("max2.msh"), msh22({"1", "2", "3", "2147483647"}, {"2147483647 4 2 0 1 1 2 3 2147483647"}));
  EXPECT_EQ(msh_cells(dir.file("max2.msh")), 1u);
}

namespace {
// Two tetrahedra sharing a face, as a legacy ASCII .vtk file; CELLS at line 11, CELL_TYPES
// after the cells (line 14 with two cells).
std::string legacy_tets(const std::string& cells, const std::string& types) {
  return "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n" + cells + types;
}
const std::string kTwoTetCells = "CELLS 2 10\n4 0 1 2 3\n4 4 2 1 3\n";
}  // namespace

// VTK reads CELL_TYPES' own count: fewer types than cells left the others uninitialised
// (a tet dropped at random), and it keeps a type in a byte (266 read as 10, a tetra).
TEST(DatasetIO, LegacyCellTypesMatchTheCellsAndAreVtkTypes) {
  TempDir dir;
  write_text(dir.file("ok.vtk"), legacy_tets(kTwoTetCells, "CELL_TYPES 2\n10\n10\n"));
  EXPECT_EQ(load_input(dir.file("ok.vtk")).mesh().num_cells(), 2u);
  write_text(dir.file("short.vtk"), legacy_tets(kTwoTetCells, "CELL_TYPES 1\n10\n"));
  std::string e = input_error([&] { load_input(dir.file("short.vtk")); });
  EXPECT_TRUE(contains(e, "short.vtk: CELL_TYPES (line 14): type count 1 differs from the cell count 2 of CELLS (line 11)"))
      << e;
  write_text(dir.file("long.vtk"), legacy_tets("CELLS 1 5\n4 0 1 2 3\n", "CELL_TYPES 2\n10\n10\n"));
  e = input_error([&] { load_input(dir.file("long.vtk")); });
  EXPECT_TRUE(contains(e, "long.vtk: CELL_TYPES (line 13): type count 2 differs from the cell count 1 of CELLS (line 11)"))
      << e;
  for (const std::string type : {"266", "9999", "-1"}) {
    write_text(dir.file("t.vtk"), legacy_tets(kTwoTetCells, "CELL_TYPES 2\n10\n" + type + "\n"));
    e = input_error([&] { load_input(dir.file("t.vtk")); });
    EXPECT_TRUE(contains(e, "t.vtk: CELL_TYPES (line 14): cell 1: type " + type + " is not a VTK cell type")) << e;
  }
  // Point indices of a pre-5.1 list are 32-bit ints to VTK ("Error reading ascii cell data!").
  write_text(dir.file("big.vtk"), legacy_tets("CELLS 2 10\n4 0 1 2 3\n4 4 2 1 1099511627776\n", "CELL_TYPES 2\n10\n10\n"));
  e = input_error([&] { load_input(dir.file("big.vtk")); });
  EXPECT_TRUE(contains(e, "big.vtk: CELLS (line 11): cell 1: point index 1099511627776 is beyond 2147483647")) << e;
  // Lines are counted through the walked lists.
  write_text(dir.file("pd.vtk"), legacy_tets(kTwoTetCells, "CELL_TYPES 2\n10\n10\nPOINT_DATA x\n"));
  e = input_error([&] { load_input(dir.file("pd.vtk")); });
  EXPECT_TRUE(contains(e, "pd.vtk: POINT_DATA (line 17): 'x' is not a valid count")) << e;
  write_text(dir.file("none.vtk"), legacy_tets(kTwoTetCells, "CELL_TYP"));
  e = input_error([&] { load_input(dir.file("none.vtk")); });
  EXPECT_TRUE(contains(e, "none.vtk: CELLS (line 11): no CELL_TYPES section follows (cell count 2; the file ends at line 14)")) << e;
  // Binary: the types are big-endian 32-bit integers; a 5.1 file's CELLS counts offsets.
  const auto be32 = [](int32_t v) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[i] = char(uint32_t(v) >> (24 - 8 * i));
    return b;
  };
  std::string bin = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n";
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      const float f = i == a + 1 ? 1.0f : 0.0f;
      uint32_t u;
      std::memcpy(&u, &f, 4);
      bin += be32(int32_t(u));
    }
  bin += "\nCELLS 1 5\n" + be32(4) + be32(0) + be32(1) + be32(2) + be32(3) + "\nCELL_TYPES 1\n";
  write_text(dir.file("b.vtk"), bin + be32(10) + "\n");
  EXPECT_EQ(load_input(dir.file("b.vtk")).mesh().num_cells(), 1u);
  write_text(dir.file("b266.vtk"), bin + be32(266) + "\n");
  e = input_error([&] { load_input(dir.file("b266.vtk")); });
  EXPECT_TRUE(contains(e, "b266.vtk: CELL_TYPES (line 9): cell 0: type 266 is not a VTK cell type")) << e;
  write_text(dir.file("v51.vtk"), "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 2 4\nOFFSETS vtktypeint64\n0 4\n"
                                  "CONNECTIVITY vtktypeint64\n0 1 2 3\nCELL_TYPES 2\n10\n10\n");
  e = input_error([&] { load_input(dir.file("v51.vtk")); });
  EXPECT_TRUE(contains(e, "v51.vtk: CELL_TYPES (line 15): type count 2 differs from the cell count 1 of CELLS (line 10)"))
      << e;
}

// A file that does not start as its format does is refused from its first bytes: gmsh ran
// a NUL-filled .msh as a .geo script (0.11 s per MB, then "no elements"), and a NUL-filled
// .vtu was read whole into memory before VTK failed at byte 0.
TEST(DatasetIO, FilesNotStartingAsTheirFormatAreRefusedAtOnce) {
  TempDir dir;
  const std::string nul(1 << 20, '\0');
  for (const char* name : {"z.msh", "z.vtu", "z.vti", "z.vtk"}) write_text(dir.file(name), nul);
  std::string e = msh_error(dir.file("z.msh"));
  EXPECT_TRUE(contains(e, "z.msh: file: is not a gmsh mesh file: it starts with "
                          "'\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00...', "
                          "not $MeshFormat")) << e;
  e = input_error([&] { load_input(dir.file("z.vtu")); });
  EXPECT_TRUE(contains(e, "z.vtu: file: is not a VTK XML file: it starts with '\\x00")) << e;
  EXPECT_TRUE(contains(e, "...', not <?xml or <VTKFile")) << e;
  e = input_error([&] { load_input(dir.file("z.vti")); });
  EXPECT_TRUE(contains(e, "z.vti: file: is not a VTK XML file")) << e;
  e = input_error([&] { load_input(dir.file("z.vtk")); });
  EXPECT_TRUE(contains(e, "z.vtk: file: is not a legacy VTK file: it starts with '\\x00")) << e;
  EXPECT_TRUE(contains(e, "...', not '# vtk DataFile Version'")) << e;
  // A .geo script named .msh is not run; blank lines before $MeshFormat make gmsh do so too.
  write_text(dir.file("geo.msh"), "Point(1) = {0, 0, 0};\n");
  e = msh_error(dir.file("geo.msh"));
  EXPECT_TRUE(contains(e, "geo.msh: file: is not a gmsh mesh file: it starts with 'Point(1) = {0, 0...', not $MeshFormat"))
      << e;
  write_text(dir.file("blank.msh"), "\n" + msh41({"1", "2", "3", "4"}, {"1 1 2 3 4"}));
  e = msh_error(dir.file("blank.msh"));
  EXPECT_TRUE(contains(e, "blank.msh: file: is not a gmsh mesh file: it starts with a blank line, not $MeshFormat")) << e;
  write_text(dir.file("empty.msh"), "");
  e = msh_error(dir.file("empty.msh"));
  EXPECT_TRUE(contains(e, "empty.msh: file: is not a gmsh mesh file: it is empty")) << e;
  write_text(dir.file("blank.vtu"), std::string(5000, ' '));
  e = input_error([&] { load_input(dir.file("blank.vtu")); });
  EXPECT_TRUE(contains(e, "blank.vtu: file: is not a VTK XML file: its first 4096 bytes are blank")) << e;
  // Blank lines before the root element are XML.
  write_text(dir.file("lead.vtu"), "\n  \n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
                                   "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>"
                                   "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1"
                                   "</DataArray></Points><Cells>"
                                   "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>"
                                   "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
                                   "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>"
                                   "</Cells></Piece></UnstructuredGrid></VTKFile>\n");
  EXPECT_EQ(load_input(dir.file("lead.vtu")).mesh().num_cells(), 1u);
}

// MSH 2 element lines and binary blocks against their tag counts: gmsh reads numbers, not
// lines, and said "Error loading ..." or "Wrong node index 0" without naming the element.
TEST(DatasetIO, GmshMsh2TagCountsAreChecked) {
  TempDir dir;
  const std::vector<std::string> nodes = {"1", "2", "3", "4"};
  write_text(dir.file("huge.msh"), msh22(nodes, {"1 4 1000000000 0 1 1 2 3 4"}));
  std::string e = msh_error(dir.file("huge.msh"));
  EXPECT_TRUE(contains(e, "huge.msh: element 1 (line 13): type 4 has 4 nodes and the tag count is 1000000000, "
                          "but the line holds 6 numbers after the tag count")) << e;
  write_text(dir.file("neg.msh"), msh22(nodes, {"1 4 -3 0 1 1 2 3 4"}));
  e = msh_error(dir.file("neg.msh"));
  EXPECT_TRUE(contains(e, "neg.msh: element 1 (line 13): tag count -3 is negative")) << e;
  write_text(dir.file("short.msh"), msh22(nodes, {"1 4 2 0 1 1 2 3"}));
  e = msh_error(dir.file("short.msh"));
  EXPECT_TRUE(contains(e, "short.msh: element 1 (line 13): type 4 has 4 nodes and the tag count is 2, "
                          "but the line holds 5 numbers")) << e;
  EXPECT_EQ(msh_cells((write_text(dir.file("ok.msh"), msh22(nodes, {"1 4 2 0 1 1 2 3 4"})), dir.file("ok.msh"))), 1u);
  // Binary: a block's type, element count and tag count, then its elements.
  const auto i32 = [](std::initializer_list<int32_t> v) {
    std::string b;
    for (const int32_t x : v) b.append(reinterpret_cast<const char*>(&x), 4);
    return b;
  };
  std::string head = "$MeshFormat\n2.2 1 8\n" + i32({1}) + "\n$EndMeshFormat\n$Nodes\n4\n";
  for (int i = 1; i <= 4; ++i) {
    head += i32({i});
    for (int a = 0; a < 3; ++a) {
      const double d = i == a + 2;
      head.append(reinterpret_cast<const char*>(&d), 8);
    }
  }
  head += "\n$EndNodes\n$Elements\n1\n";
  const std::string tail = "\n$EndElements\n";
  write_text(dir.file("b.msh"), head + i32({4, 1, 2, 1, 0, 1, 1, 2, 3, 4}) + tail);
  EXPECT_EQ(msh_cells(dir.file("b.msh")), 1u);
  write_text(dir.file("bneg.msh"), head + i32({4, 1, -7, 1, 0, 1, 1, 2, 3, 4}) + tail);
  e = msh_error(dir.file("bneg.msh"));
  EXPECT_TRUE(contains(e, "bneg.msh: $Elements (byte 184): block of type 4: tag count -7 is negative")) << e;
  write_text(dir.file("bbig.msh"), head + i32({4, 2000000000, 2, 1, 0, 1, 1, 2, 3, 4}) + tail);
  e = msh_error(dir.file("bbig.msh"));
  EXPECT_TRUE(contains(e, "bbig.msh: $Elements (byte 184): block of type 4: element count 2000000000 is not within "
                          "the 1 elements left of the section's 1")) << e;
}

// gmsh reads $NodeData's value count into an int: 10^12 values declared (2 given) dropped
// the view without a word and the mesh was read without its scalars.
TEST(DatasetIO, GmshNodeDataCountBeyondTheFileIsRefused) {
  TempDir dir;
  const std::string mesh = msh22({"1", "2", "3", "4"}, {"1 4 2 0 1 1 2 3 4"});
  const auto data = [](const std::string& count, const std::string& values) {
    return "$NodeData\n1\n\"s\"\n1\n0.0\n3\n0\n1\n" + count + "\n" + values + "$EndNodeData\n";
  };
  write_text(dir.file("ok.msh"), mesh + data("4", "1 0\n2 1\n3 2\n4 3\n"));
  EXPECT_EQ(msh_cells(dir.file("ok.msh")), 1u);
  write_text(dir.file("huge.msh"), mesh + data("1000000000000", "1 0\n2 1\n"));
  std::string e = msh_error(dir.file("huge.msh"));
  EXPECT_TRUE(contains(e, "huge.msh: NodeData \"s\": declares 1000000000000 values but only 53 bytes follow")) << e;
  write_text(dir.file("neg.msh"), mesh + data("-2", "1 0\n2 1\n"));
  e = msh_error(dir.file("neg.msh"));
  EXPECT_TRUE(contains(e, "neg.msh: NodeData \"s\": declares -2 values")) << e;
}

// gmsh reads a file with CRLF line ends as with LF, but the prescans looked for "\n" after
// "$MeshFormat" and the section lines and skipped such a file whole: a node tag of 3e9
// crashed gmsh (SIGSEGV) in MSH 4.1 and was narrowed silently in MSH 2.2.
TEST(DatasetIO, GmshCrlfFilesGetTheSameChecks) {
  TempDir dir;
  const auto crlf = [](std::string s) {
    for (size_t at = s.find('\n'); at != std::string::npos; at = s.find('\n', at + 2)) s.insert(at, 1, '\r');
    return s;
  };
  const std::string data = "$NodeData\n1\n\"s\"\n1\n0.0\n3\n0\n1\n1000000000000\n1 0\n$EndNodeData\n";
  const std::string comments = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Comments\nmade by hand\n$EndComments\n";
  std::string count22 = msh22({"1", "2", "3", "4"}, {"1 4 2 0 1 1 2 3 4"});
  count22.insert(count22.find("$Elements\n1") + 11, "000000000");  // 10^9 elements declared
  const std::pair<const char*, std::string> bad[] = {
      {"tag41", msh41({"1", "2", "3", "3000000000"}, {"1 1 2 3 3000000000"})},
      {"tag22", msh22({"1", "2", "3", "3000000000"}, {"1 4 2 0 1 1 2 3 3000000000"})},
      {"count22", count22},
      {"data22", msh22({"1", "2", "3", "4"}, {"1 4 2 0 1 1 2 3 4"}) + data},
      {"skip22", comments + msh22({"1", "2", "3", "4"}, {"1 4 2 0 1 1 2 3 9"}).substr(std::strlen("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"))},
  };
  for (const auto& [name, text] : bad) {
    SCOPED_TRACE(name);
    write_text(dir.file(std::string(name) + ".msh"), text);
    write_text(dir.file(std::string(name) + "_crlf.msh"), crlf(text));
    // The same element and reason (a byte count after "but only" counts the '\r's).
    const auto reason = [](const std::string& e) { return e.substr(e.find(".msh: ") + 6, e.find("but only") - e.find(".msh: ") - 6); };
    const std::string lf = msh_error(dir.file(std::string(name) + ".msh"));
    const std::string cr = msh_error(dir.file(std::string(name) + "_crlf.msh"));
    EXPECT_EQ(reason(cr), reason(lf)) << cr;
    EXPECT_FALSE(contains(cr, "gmsh:")) << cr;
  }
  write_text(dir.file("ok41.msh"), crlf(msh41({"1", "2", "3", "4", "5"}, {"1 1 2 3 4", "2 2 3 4 5"})));
  EXPECT_EQ(msh_cells(dir.file("ok41.msh")), 2u);
  write_text(dir.file("ok22.msh"), crlf(comments + msh22({"1", "2", "3", "4"}, {"1 4 2 0 1 1 2 3 4"}).substr(
                                        std::strlen("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"))));
  EXPECT_EQ(msh_cells(dir.file("ok22.msh")), 1u);
}

// VTK reads ASCII legacy numbers with `>>`, which stops at "nan", "inf" or a missing value
// and said only "Error reading ascii data. Possible mismatch of datasize with declaration".
TEST(DatasetIO, LegacyAsciiNumbersAreNamedWhenNotFinite) {
  TempDir dir;
  const auto refused = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string text = gmsh_like_vtk();
    text.replace(text.find(from), from.size(), to);
    write_text(dir.file(name), text);
    return input_error([&] { load_input(dir.file(name)); });
  };
  std::string e = refused("nan.vtk", "1 1 0\n", "1 nan 0\n");
  EXPECT_TRUE(contains(e, "nan.vtk: point 2 (line 8): a coordinate is 'nan', not a finite number")) << e;
  e = refused("word.vtk", "0 0 1\n", "0 0 1,\n");
  EXPECT_TRUE(contains(e, "word.vtk: point 4 (line 10): a coordinate is '1,', not a finite number")) << e;
  e = refused("short.vtk", "POINTS 9 double", "POINTS 10 double");
  EXPECT_TRUE(contains(e, "short.vtk: POINTS (line 5): holds 27 of its 30 values, then 'CELLS' at line 15")) << e;
  e = refused("inf.vtk", "0 1 2 3 4 5 6 7 8\n", "0 1 2 inf 4 5 6 7 8\n");
  EXPECT_TRUE(contains(e, "inf.vtk: point 3 (line 28): scalar 's' is 'inf', not a finite number")) << e;
  std::string text = gmsh_like_vtk();
  text.replace(text.find("POINTS 9 double"), 15, "POINTS 9 float");
  text.replace(text.find("0.5 0.5 0.5"), 11, "0.5 1e39 0.5");
  write_text(dir.file("float.vtk"), text);
  e = input_error([&] { load_input(dir.file("float.vtk")); });
  EXPECT_TRUE(contains(e, "float.vtk: point 8 (line 14): a coordinate is '1e39', beyond float's range")) << e;
  text.replace(text.find("1e39"), 4, "1e38");
  write_text(dir.file("float.vtk"), text);
  EXPECT_EQ(load_input(dir.file("float.vtk")).mesh().num_points(), 9u);
}

namespace {
// Two tetrahedra sharing a face as an ASCII .vtu; `cells` is NumberOfCells, `types` the
// types array's text.
std::string ascii_vtu(const std::string& cells, const std::string& types) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
         "<UnstructuredGrid><Piece NumberOfPoints=\"5\" NumberOfCells=\"" + cells + "\"><Points>"
         "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1 1 1 1"
         "</DataArray></Points><Cells>"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4 2 1 3</DataArray>"
         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 8</DataArray>"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + types + "</DataArray>"
         "</Cells></Piece></UnstructuredGrid></VTKFile>\n";
}
}  // namespace

// VTK reads NumberOfCells offsets and types and ignores the rest (a cell dropped silently),
// and parses an ASCII UInt8 "266" as 10, a tetra.
TEST(DatasetIO, VtuCellArraysHoldNumberOfCellsVtkTypes) {
  TempDir dir;
  write_text(dir.file("ok.vtu"), ascii_vtu("2", "10 10"));
  EXPECT_EQ(load_input(dir.file("ok.vtu")).mesh().num_cells(), 2u);
  write_text(dir.file("less.vtu"), ascii_vtu("1", "10 10"));
  std::string e = input_error([&] { load_input(dir.file("less.vtu")); });
  EXPECT_TRUE(contains(e, "less.vtu: Cells DataArray 'offsets': its value count 2 differs from the Piece's NumberOfCells 1"))
      << e;
  write_text(dir.file("t.vtu"), ascii_vtu("2", "10 266"));
  e = input_error([&] { load_input(dir.file("t.vtu")); });
  EXPECT_TRUE(contains(e, "t.vtu: Cells DataArray 'types': cell 1: type '266' is not a VTK cell type")) << e;
  // Appended raw data: counted from the arrays' headers.
  write_scene(make("zoo"), dir.file("zoo.vtu"));
  std::ifstream in(dir.file("zoo.vtu"), std::ios::binary);
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  const size_t at = text.find("NumberOfCells=\"") + 15;
  const std::string n = text.substr(at, text.find('"', at) - at);
  text.replace(at, n.size(), std::to_string(std::stoi(n) - 1));
  write_text(dir.file("zoo_less.vtu"), text);
  e = input_error([&] { load_input(dir.file("zoo_less.vtu")); });
  EXPECT_TRUE(contains(e, "zoo_less.vtu: Cells DataArray 'offsets': its value count " + n +
                              " differs from the Piece's NumberOfCells " + std::to_string(std::stoi(n) - 1)))
      << e;
}

namespace {
// ascii_vtu("2", "10 10") with `from` replaced by `to` (a Cells array's type or values).
std::string ascii_vtu_with(const std::string& from, const std::string& to) {
  std::string s = ascii_vtu("2", "10 10");
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}
}  // namespace

// VTK reads an ASCII 8-bit array as a wider integer narrowed unchecked: point index "260" in
// a UInt8 connectivity array was read as 4, a real point, and the mesh silently changed.
TEST(DatasetIO, VtuCharConnectivityIsRefused) {
  TempDir dir;
  const std::string conn = "type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4";
  write_text(dir.file("u8.vtu"), ascii_vtu_with(conn, "type=\"UInt8\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 260"));
  std::string e = input_error([&] { load_input(dir.file("u8.vtu")); });
  EXPECT_TRUE(contains(e, "u8.vtu: Cells DataArray 'connectivity': type UInt8 is too narrow for point indices")) << e;
  write_text(dir.file("i8.vtu"), ascii_vtu_with(conn, "type=\"Int8\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4"));
  e = input_error([&] { load_input(dir.file("i8.vtu")); });
  EXPECT_TRUE(contains(e, "i8.vtu: Cells DataArray 'connectivity': type Int8 is too narrow for point indices")) << e;
  write_text(dir.file("o8.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"offsets\"", "type=\"UInt8\" Name=\"offsets\""));
  e = input_error([&] { load_input(dir.file("o8.vtu")); });
  EXPECT_TRUE(contains(e, "o8.vtu: Cells DataArray 'offsets': type UInt8 is too narrow")) << e;
  // 16-bit indices are integers wide enough to be read exactly.
  write_text(dir.file("u16.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"connectivity\"", "type=\"UInt16\" Name=\"connectivity\""));
  EXPECT_EQ(load_input(dir.file("u16.vtu")).mesh().num_cells(), 2u);
}

// Point indices and cell types stored as floats are malformed: VTK casts them (3.5 read as
// 3), so integral values read and others were cut silently. Refused whatever the values.
TEST(DatasetIO, VtuFloatCellArraysAreRefused) {
  TempDir dir;
  write_text(dir.file("c.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"connectivity\"", "type=\"Float64\" Name=\"connectivity\""));
  std::string e = input_error([&] { load_input(dir.file("c.vtu")); });
  EXPECT_TRUE(contains(e, "c.vtu: Cells DataArray 'connectivity': type 'Float64' is not an integer type (Int16 to UInt64; "
                          "VTK would cast 3.5 to 3)")) << e;
  write_text(dir.file("o.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"offsets\"", "type=\"Float32\" Name=\"offsets\""));
  e = input_error([&] { load_input(dir.file("o.vtu")); });
  EXPECT_TRUE(contains(e, "o.vtu: Cells DataArray 'offsets': type 'Float32' is not an integer type")) << e;
  write_text(dir.file("t.vtu"), ascii_vtu_with("type=\"UInt8\" Name=\"types\"", "type=\"Float32\" Name=\"types\""));
  e = input_error([&] { load_input(dir.file("t.vtu")); });
  EXPECT_TRUE(contains(e, "t.vtu: Cells DataArray 'types': type 'Float32' is not an integer type (Int8 to UInt64; ")) << e;
}

namespace {
// `n` as `bytes` little-endian bytes.
std::string le(uint64_t n, size_t bytes) {
  std::string s;
  for (size_t b = 0; b < bytes; ++b) s += char(n >> (8 * b) & 0xFF);
  return s;
}
std::string base64(const std::string& raw) {
  const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < raw.size(); i += 3) {
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = v << 8 | (i + k < raw.size() ? uint8_t(raw[i + k]) : 0);
    for (size_t k = 0; k < 4; ++k) out += k <= raw.size() - i ? digits[v >> (18 - 6 * k) & 63] : '=';
  }
  return out;
}
// Two tetrahedra as an uncompressed .vtu, arrays "appended" (raw) or "binary" (inline base64),
// each with its UInt32 byte count; `huge` names the array whose count is 4294967040.
std::string binary_vtu(const std::string& format, const std::string& huge) {
  const double pts[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  std::string points(reinterpret_cast<const char*>(pts), sizeof pts), conn, offsets;
  for (const int64_t i : {0, 1, 2, 3, 4, 2, 1, 3}) conn += le(uint64_t(i), 8);
  offsets = le(4, 8) + le(8, 8);
  struct Array { const char *parent, *name, *type; int comps; std::string data; };
  const Array arrays[] = {{"Points", "Points", "Float64", 3, points}, {"Cells", "connectivity", "Int64", 1, conn},
                          {"Cells", "offsets", "Int64", 1, offsets}, {"Cells", "types", "UInt8", 1, "\x0a\x0a"}};
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
                    "header_type=\"UInt32\">\n<UnstructuredGrid><Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">";
  std::string appended;
  for (const Array& a : arrays) {
    if (a.name == std::string("Points")) xml += "<Points>";
    if (a.name == std::string("connectivity")) xml += "</Points><Cells>";
    const std::string head = le(a.name == huge ? 4294967040u : a.data.size(), 4);
    xml += std::string("<DataArray type=\"") + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
           std::to_string(a.comps) + "\" format=\"" + format + "\"";
    if (format == "appended") {
      xml += " offset=\"" + std::to_string(appended.size()) + "\"/>";
      appended += head + a.data;
    } else {
      xml += ">" + base64(head) + base64(a.data) + "</DataArray>";
    }
  }
  xml += "</Cells></Piece></UnstructuredGrid>";
  if (format == "appended") xml += "<AppendedData encoding=\"raw\">_" + appended + "</AppendedData>";
  return xml + "</VTKFile>\n";
}
}  // namespace

// A binary or appended array's header declaring more bytes than follow it: VTK read the
// values it needed and took the rest on trust (the file accepted); a compressed header's
// block count it allocates before reading (2^31 blocks: 8 GB, then its own error).
TEST(DatasetIO, VtuDataHeadersBeyondTheFileAreRefused) {
  TempDir dir;
  for (const std::string format : {"appended", "binary"}) {
    write_text(dir.file(format + ".vtu"), binary_vtu(format, ""));
    EXPECT_EQ(load_input(dir.file(format + ".vtu")).mesh().num_cells(), 2u) << format;
    for (const std::string array : {"Points", "connectivity"}) {
      const std::string f = dir.file(format + "_" + array + ".vtu");
      write_text(f, binary_vtu(format, array));
      const std::string e = input_error([&] { load_input(f); });
      EXPECT_TRUE(contains(e, format + "_" + array + ".vtu: " + (array == "Points" ? "Points" : "Cells") +
                                  " DataArray '" + array + "': its header declares 4294967040 bytes of data, but only "))
          << e;
    }
  }
  // Compressed (as vobench writes): the connectivity's block count made 2^31 - 16.
  write_scene(make("zoo"), dir.file("zoo.vtu"));
  std::ifstream in(dir.file("zoo.vtu"), std::ios::binary);
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  const size_t conn = text.find("Name=\"connectivity\"");
  const size_t at = text.find("offset=\"", conn) + 8;
  const size_t data = text.find('_', text.find("<AppendedData")) + 1 + std::stoul(text.substr(at));
  ASSERT_NE(text.find("header_type=\"UInt32\""), std::string::npos);
  text.replace(data, 4, le(0x7FFFFFF0, 4));
  write_text(dir.file("zoo_blocks.vtu"), text);
  const std::string e = input_error([&] { load_input(dir.file("zoo_blocks.vtu")); });
  EXPECT_TRUE(contains(e, "zoo_blocks.vtu: Cells DataArray 'connectivity': its header declares 2147483632 compressed blocks, "
                          "but only "))
      << e;
}
