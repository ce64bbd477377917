// PLY surfaces as VTK's reader takes them, checked by the prescan first.
#include <cstdint>

#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

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
