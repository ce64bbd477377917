// VTK XML .vtu files: cells beside the volume cells, and what the XML prescan refuses before
// VTK reads a file.
#include <cstdint>
#include <fstream>
#include <sstream>

#include <zlib.h>

#include "datasets/io/vtk_io.h"
#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

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
TEST(DatasetIO, VtuCharConnectivityOutOfRangeIsRefused) {
  TempDir dir;
  const std::string conn = "type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4";
  write_text(dir.file("u8.vtu"), ascii_vtu_with(conn, "type=\"UInt8\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 260"));
  std::string e = input_error([&] { load_input(dir.file("u8.vtu")); });
  EXPECT_TRUE(contains(e, "u8.vtu: Cells DataArray 'connectivity': value 4 (260) is outside UInt8 (0 to 255")) << e;
  write_text(dir.file("i8.vtu"), ascii_vtu_with(conn, "type=\"Int8\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 200"));
  e = input_error([&] { load_input(dir.file("i8.vtu")); });
  EXPECT_TRUE(contains(e, "i8.vtu: Cells DataArray 'connectivity': value 4 (200) is outside Int8 (-128 to 127")) << e;
  // 8-bit indices within their type are what they say: a small mesh may store them so.
  write_text(dir.file("ok8.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"connectivity\"", "type=\"UInt8\" Name=\"connectivity\""));
  EXPECT_EQ(load_input(dir.file("ok8.vtu")).mesh().num_cells(), 2u);
  write_text(dir.file("o8.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"offsets\"", "type=\"Int8\" Name=\"offsets\""));
  EXPECT_EQ(load_input(dir.file("o8.vtu")).mesh().num_cells(), 2u);
  // 16-bit indices likewise.
  write_text(dir.file("u16.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"connectivity\"", "type=\"UInt16\" Name=\"connectivity\""));
  EXPECT_EQ(load_input(dir.file("u16.vtu")).mesh().num_cells(), 2u);
}

// Point indices and cell types stored as floats are malformed: VTK casts them (3.5 read as
// 3), so integral values read and others were cut silently. Refused whatever the values.
TEST(DatasetIO, VtuFloatCellArraysAreRefused) {
  TempDir dir;
  write_text(dir.file("c.vtu"), ascii_vtu_with("type=\"Int64\" Name=\"connectivity\"", "type=\"Float64\" Name=\"connectivity\""));
  std::string e = input_error([&] { load_input(dir.file("c.vtu")); });
  EXPECT_TRUE(contains(e, "c.vtu: Cells DataArray 'connectivity': type 'Float64' is not an integer type (Int8 to UInt64; "
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

// A .vti image is one piece over its WholeExtent, each point (cell) array one tuple per point
// (cell): VTK read 10 ASCII values into 8 points and a Piece Extent of 12 points under a
// WholeExtent of 8, both silently.
TEST(DatasetIO, VtiArraysAndPieceMatchTheExtent) {
  TempDir dir;
  const auto vti = [&](const char* name, const std::string& extent, const std::string& values,
                       const std::string& data = "PointData") {
    write_text(dir.file(name), "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                               "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
                               "<Piece Extent=\"" + extent + "\">\n<" + data + " Scalars=\"v\">\n"
                               "<DataArray type=\"Float32\" Name=\"v\" format=\"ascii\">" + values + "</DataArray>\n</" +
                               data + ">\n</Piece>\n</ImageData>\n</VTKFile>\n");
    return dir.file(name);
  };
  EXPECT_EQ(load_input(vti("good.vti", "0 1 0 1 0 1", "1 2 3 4 5 6 7 8")).grid().num_voxels(), 8u);
  std::string e = input_error([&] { load_input(vti("long.vti", "0 1 0 1 0 1", "1 2 3 4 5 6 7 8 9 10")); });
  EXPECT_TRUE(contains(e, "long.vti: PointData DataArray 'v': holds 10 values, but its Piece's extent has 8")) << e;
  e = input_error([&] { load_input(vti("short.vti", "0 1 0 1 0 1", "1 2 3 4 5 6 7")); });
  EXPECT_TRUE(contains(e, "short.vti: PointData DataArray 'v': holds 7 values")) << e;
  e = input_error([&] { load_input(vti("cells.vti", "0 1 0 1 0 1", "1 2", "CellData")); });
  EXPECT_TRUE(contains(e, "cells.vti: CellData DataArray 'v': holds 2 values, but its Piece's extent has 1")) << e;
  e = input_error([&] { load_input(vti("piece.vti", "0 1 0 1 0 2", "1 2 3 4 5 6 7 8")); });
  EXPECT_TRUE(contains(e, "piece.vti: Piece Extent: '0 1 0 1 0 2' is not the WholeExtent '0 1 0 1 0 1'")) << e;
}

namespace {
// A .vti over WholeExtent 0 1 0 1 0 1 (8 points) whose point array 'v' (Float32) is appended
// with `values` values, raw or base64, zlib-compressed (one block) or not.
std::string appended_vti(size_t values, bool base64_encoded, bool compressed) {
  std::string data;
  for (size_t i = 0; i < values; ++i) {
    const float f = float(i);
    data.append(reinterpret_cast<const char*>(&f), sizeof f);
  }
  std::string head = le(data.size(), 4);
  if (compressed) {
    std::string z(compressBound(uLong(data.size())), '\0');
    uLongf zn = uLongf(z.size());
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(z.data()), &zn, reinterpret_cast<const Bytef*>(data.data()),
                        uLong(data.size()), 6), Z_OK);
    z.resize(zn);
    head = le(1, 4) + le(32768, 4) + le(data.size(), 4) + le(z.size(), 4);
    data = z;
  }
  return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                     "header_type=\"UInt32\"") + (compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") +
         ">\n<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
         "<Piece Extent=\"0 1 0 1 0 1\">\n<PointData Scalars=\"v\">\n"
         "<DataArray type=\"Float32\" Name=\"v\" format=\"appended\" offset=\"0\"/>\n</PointData>\n</Piece>\n"
         "</ImageData>\n<AppendedData encoding=\"" + (base64_encoded ? "base64" : "raw") + "\">\n_" +
         (base64_encoded ? base64(head) + base64(data) : head + data) + "\n</AppendedData>\n</VTKFile>\n";
}
}  // namespace

// An appended image array is counted against the extent as an inline one: VTK read 10
// appended values into 8 points silently (and 6 with "Error reading extent", naming no array).
TEST(DatasetIO, VtiAppendedArraysMatchTheExtent) {
  TempDir dir;
  for (const bool b64 : {false, true})
    for (const bool z : {false, true}) {
      const std::string stem = std::string(b64 ? "b64" : "raw") + (z ? "_z" : "");
      write_text(dir.file(stem + "_8.vti"), appended_vti(8, b64, z));
      EXPECT_EQ(load_input(dir.file(stem + "_8.vti")).grid().num_voxels(), 8u) << stem;
      for (const size_t n : {10, 6}) {
        const std::string f = stem + "_" + std::to_string(n) + ".vti";
        write_text(dir.file(f), appended_vti(n, b64, z));
        const std::string e = input_error([&] { load_input(dir.file(f)); });
        EXPECT_TRUE(contains(e, f + ": PointData DataArray 'v': holds " + std::to_string(n) +
                                    " values (by its header), but its Piece's extent has 8 (points times components)"))
            << e;
      }
    }
}
