// The exact interpenetration test: touching in every way is not overlapping, any overlap
// (however small) is; the box stage finds what a brute-force all-pairs test finds.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/scene/cell_overlap.h"
#include "tests/harness/scene/overlap_meshes.h"

using namespace vob;
using namespace vob::test;

namespace {

const Vec3 O{0, 0, 0}, X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};

bool overlap(const CellMesh& m) {
  validate_cell_mesh(m, "pair");
  return cells_interpenetrate(m, 0, 1);
}

std::vector<std::pair<int32_t, int32_t>> brute_force(const CellMesh& m) {
  std::vector<std::pair<int32_t, int32_t>> out;
  for (int32_t a = 0; a < int32_t(m.num_cells()); ++a)
    for (int32_t b = a + 1; b < int32_t(m.num_cells()); ++b)
      if (cells_interpenetrate(m, a, b)) out.emplace_back(a, b);
  return out;
}

}  // namespace

TEST(CellOverlap, SharedFaceOnSharedNodesIsNotOverlap) {
  CellMesh m;
  m.points = {O, X, Y, Z, {1, 1, 1}};
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.add_cell(CellType::Tetra, {1, 2, 3, 4});
  EXPECT_FALSE(overlap(m));
}

TEST(CellOverlap, TouchingWithDuplicatedNodesIsNotOverlap) {
  // Face to face, the same triangle.
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, X, Y, Z, {1, 1, 1})));
  // Along an edge only.
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, X, Y, {1, 1, 0}, {1, 1, -1})));
  // At a vertex only.
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, O, -X, -Y, -Z)));
  // Coplanar faces that overlap in part of their area (a non-conforming contact).
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, {0.3, 0.2, 0}, {1.3, 0.2, 0}, {0.3, 1.2, 0}, {0.3, 0.2, -1})));
}

TEST(CellOverlap, CrossingEdgesNeedTheEdgeEdgePlane) {
  // Edges crossing at the origin, one tet below z = 0 and one above: no face plane of
  // either separates them, only the plane spanned by the two edges.
  const Vec3 a0{-1, 0, 0}, a1{1, 0, 0}, a2{0, 1, -1}, a3{0, -1, -1};
  const Vec3 b0{0, -1, 0}, b1{0, 1, 0}, b2{1, 0, 1}, b3{-1, 0, 1};
  EXPECT_FALSE(overlap(tet_pair(a0, a1, a2, a3, b0, b1, b2, b3)));
  const Vec3 down{0, 0, -1e-13};
  EXPECT_TRUE(overlap(tet_pair(a0, a1, a2, a3, b0 + down, b1 + down, b2 + down, b3 + down)));
}

TEST(CellOverlap, ATinyShiftIntoTheOtherIsCaught) {
  const Vec3 in = Vec3{-1, -1, -1} * 1e-12;  // moves the second tet into the first
  EXPECT_TRUE(overlap(tet_pair(O, X, Y, Z, X + in, Y + in, Z + in, Vec3{1, 1, 1} + in)));
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, X - in, Y - in, Z - in, Vec3{1, 1, 1} - in)));
  // One coordinate one ulp into the first tet.
  const Vec3 x_in{std::nextafter(1.0, 0.0), 0, 0};
  EXPECT_TRUE(overlap(tet_pair(O, X, Y, Z, x_in, Y, Z, {1, 1, 1})));
  // Face to face, the second raised by 1e-15 into the first.
  const Vec3 up{0, 0, 1e-15};
  EXPECT_TRUE(overlap(tet_pair(O, X, Y, Z, Vec3{0.3, 0.2, 0} + up, Vec3{1.3, 0.2, 0} + up,
                               Vec3{0.3, 1.2, 0} + up, Vec3{0.3, 0.2, -1} + up)));
}

TEST(CellOverlap, SameCellTwiceAndContainedCellOverlap) {
  EXPECT_TRUE(overlap(tet_pair(O, X, Y, Z, O, X, Y, Z)));
  const Vec3 c{0.1, 0.1, 0.1};
  EXPECT_TRUE(overlap(tet_pair(O, X, Y, Z, c, c + X * 0.1, c + Y * 0.1, c + Z * 0.1)));
  EXPECT_FALSE(overlap(tet_pair(O, X, Y, Z, O + X * 2, X * 3, X * 2 + Y, X * 2 + Z)));
}

TEST(CellOverlap, ValidBlocksHaveNoPairs) {
  for (const CellMesh& m : {tet_block(3), tet_block(4, 1.0, 0.2, 7)}) {
    validate_cell_mesh(m, "block");
    const CellOverlapReport r = find_overlapping_cells(m);
    EXPECT_GT(r.candidates, int64_t(m.num_cells()));  // neighbours' boxes do overlap
    EXPECT_TRUE(r.pairs.empty()) << describe_overlap("block", r);
  }
  // Axis-aligned hexahedra: half-open boxes only touch, so there is nothing to decide.
  const CellMesh hexes = hex_block(3);
  const CellOverlapReport r = find_overlapping_cells(hexes);
  EXPECT_EQ(r.candidates, 0);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_TRUE(brute_force(hexes).empty());
}

TEST(CellOverlap, BlocksTouchingThroughDuplicatedNodesHaveNoPairs) {
  const CellMesh conforming = appended(tet_block(2), translated(tet_block(2), {2, 0, 0}));
  const CellMesh nonconforming = appended(tet_block(2), translated(tet_block(4, 0.5), {2, 0, 0}));
  const CellMesh hexes = appended(hex_block(2), translated(hex_block(2), {0, 0, 2}));
  for (const CellMesh* m : {&conforming, &nonconforming, &hexes}) {
    validate_cell_mesh(*m, "blocks");
    EXPECT_TRUE(find_overlapping_cells(*m).pairs.empty());
    EXPECT_TRUE(brute_force(*m).empty());
  }
}

TEST(CellOverlap, InterpenetratingBlocksGiveWhatBruteForceGives) {
  const CellMesh m = interpenetrating_blocks(2);
  validate_cell_mesh(m, "blocks");
  const CellOverlapReport r = find_overlapping_cells(m);
  const auto expected = brute_force(m);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(r.pairs, expected);
  for (const auto& [a, b] : r.pairs) EXPECT_TRUE(a < 48 && b >= 48) << a << " " << b;
  EXPECT_NE(describe_overlap("blocks", r).find("cells " + std::to_string(expected[0].first) + " and " +
                                               std::to_string(expected[0].second)),
            std::string::npos);
}

TEST(CellOverlap, HexahedraSharingANonPlanarQuadAreNeighbours) {
  // Two unit hexahedra stacked along z whose shared quad is bent (one corner raised):
  // their hulls would overlap in the sliver between the quad's two triangulations, but
  // they lie on either side of the face.
  CellMesh lower;
  lower.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1.05}, {0, 1, 1}};
  lower.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  CellMesh upper;
  upper.points = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1.05}, {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  upper.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_FALSE(overlap(appended(lower, upper)));
  EXPECT_TRUE(overlap(appended(lower, translated(upper, {0, 0, -0.01}))));
  EXPECT_TRUE(overlap(appended(lower, lower)));
}
