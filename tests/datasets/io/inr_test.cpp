// INRIMAGE volumes: header types, endianness and truncation.

#include <zlib.h>

#include <fstream>
#include <iterator>

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

// .inr.gz through zlib's inflate: members concatenated read as one stream (as gzip reads
// them); bytes after the last member were ignored by gzread (accepted), and a corrupt
// member's message said "at byte 0" and repeated the path.
TEST(DatasetIO, InrGzMembersAndWhatFollowsThem) {
  TempDir dir;
  std::string h = "#INRIMAGE-4#{\nXDIM=2\nYDIM=1\nZDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\nCPU=decm\n";
  h += std::string(252 - h.size(), '\n') + "##}\n";
  const auto gz = [&](const std::string& text) {
    const std::string tmp = dir.file("member.gz");
    gzFile f = gzopen(tmp.c_str(), "wb");
    gzwrite(f, text.data(), unsigned(text.size()));
    gzclose(f);
    std::ifstream in(tmp, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  write_text(dir.file("one.inr.gz"), gz(h + "\x03\x04"));
  EXPECT_EQ(load_input(dir.file("one.inr.gz")).grid().values, (std::vector<float>{3, 4}));
  write_text(dir.file("two.inr.gz"), gz(h + "\x03") + gz("\x04"));
  EXPECT_EQ(load_input(dir.file("two.inr.gz")).grid().values, (std::vector<float>{3, 4}));
  const std::string good = gz(h + "\x03\x04");
  write_text(dir.file("junk.inr.gz"), good + "garbage!");
  std::string e = input_error([&] { load_input(dir.file("junk.inr.gz")); });
  EXPECT_TRUE(contains(e, "junk.inr.gz: gzip member 1: ends at byte " + std::to_string(good.size()) +
                              " but 8 bytes follow it that are not another gzip member")) << e;
  std::string bad = good;
  bad[bad.size() - 6] ^= 0x5a;  // the CRC-32
  write_text(dir.file("crc.inr.gz"), bad);
  e = input_error([&] { load_input(dir.file("crc.inr.gz")); });
  EXPECT_TRUE(contains(e, "crc.inr.gz: gzip member 1: corrupt near compressed byte")) << e;
  EXPECT_TRUE(contains(e, "does not match the member's CRC-32")) << e;
  EXPECT_EQ(e.find(dir.file("crc.inr.gz")), e.rfind(dir.file("crc.inr.gz"))) << e;  // the path once
  write_text(dir.file("cut.inr.gz"), good.substr(0, good.size() - 3));
  e = input_error([&] { load_input(dir.file("cut.inr.gz")); });
  EXPECT_TRUE(contains(e, "cut.inr.gz: gzip member 1: file ends inside the compressed data")) << e;
}
