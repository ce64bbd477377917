// TetGen .node/.ele files: indices, comments and attributes, and malformed pairs.

#include "tests/datasets/io/io_test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
const char* kTwoTetsNode = "# two tetrahedra sharing a face\n5 3 1 0\n1 0 0 0 0.5\n2 1 0 0 1\n3 0 1 0 2\n4 0 0 1 3\n5 1 1 1 4\n";
const char* kTwoTetsEle = "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n";
}  // namespace

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
