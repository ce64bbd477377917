// Writing and reading scenes by file extension: exact round trips, files refused for their
// extension or their first bytes, and one InputError line per bad file.
#include <cstdio>
#include <filesystem>

#include "datasets/io/vtk_io.h"
#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
void expect_same(const CellMesh& a, const CellMesh& b) {
  EXPECT_TRUE(a.points == b.points);
  EXPECT_EQ(a.scalars, b.scalars);
  EXPECT_EQ(a.types, b.types);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.conn, b.conn);
}
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
