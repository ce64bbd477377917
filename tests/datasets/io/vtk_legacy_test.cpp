// Legacy .vtk files: voxels, cells beside the volume cells, and what the legacy prescan
// refuses before VTK reads a file.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "datasets/io/vtk_io.h"
#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

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
