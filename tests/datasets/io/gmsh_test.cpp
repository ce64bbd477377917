// gmsh .msh files (MSH 2.2 and 4.1), read through the program: what the prescans refuse
// before gmsh reads a file.
#include <cstdint>
#include <cstring>

#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

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
