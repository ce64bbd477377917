// INRIMAGE volumes: header types, endianness and truncation.

#include "datasets/io/inr_reader.h"
#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

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
