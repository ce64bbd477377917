// The exact interpenetration test: touching in every way is not overlapping, any overlap
// (however small) is; the box stage finds what a brute-force all-pairs test finds. Cells
// with warped quads are also judged as the oracle models them (CellOverlapWarped).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "harness/bench/suite.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/cell_overlap_detail.h"
#include "harness/scene/cell_planes.h"
#include "harness/scene/mesh_faces.h"
#include "tests/support/test_meshes.h"

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
  for (const CellMesh& m : {kuhn_block(3), kuhn_block(4, 1.0, 0.2, 7)}) {
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
  const CellMesh conforming = append(kuhn_block(2), translated(kuhn_block(2), {2, 0, 0}));
  const CellMesh nonconforming = append(kuhn_block(2), translated(kuhn_block(4, 0.5), {2, 0, 0}));
  const CellMesh hexes = append(hex_block(2), translated(hex_block(2), {0, 0, 2}));
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
  EXPECT_FALSE(overlap(append(lower, upper)));
  EXPECT_TRUE(overlap(append(lower, translated(upper, {0, 0, -0.01}))));
  EXPECT_TRUE(overlap(append(lower, lower)));
}

// The fast path (certify_cells_disjoint: boundary triangles against the cells they meet,
// one nesting sample per face-connected component) against the exhaustive search.
namespace {

OverlapCertificate certify(const CellMesh& m, const std::string& what) {
  validate_cell_mesh(m, what);
  const MeshFaces faces = build_mesh_faces(m, what);
  const OverlapCertificate c = certify_cells_disjoint(m, faces);
  const CellOverlapReport full = find_overlapping_cells(m);
  if (c.result == OverlapCertificate::Undecided) {
    EXPECT_FALSE(c.why.empty()) << what;
  } else {
    EXPECT_EQ(c.result == OverlapCertificate::Overlap, !full.pairs.empty()) << what;
  }
  if (c.result == OverlapCertificate::Overlap) {
    EXPECT_TRUE(cells_interpenetrate(m, c.witness.first, c.witness.second)) << what;
    EXPECT_TRUE(std::binary_search(full.pairs.begin(), full.pairs.end(), c.witness)) << what;
  }
  // The default search lists exactly what the exhaustive one lists.
  const CellOverlapReport r = check_overlapping_cells(m, faces);
  EXPECT_EQ(r.pairs, full.pairs) << what;
  EXPECT_EQ(r.method, c.result == OverlapCertificate::Clean ? "boundary" : "exhaustive") << what;
  return c;
}

CellMesh dataset(const std::string& name, std::map<std::string, std::string> set = {}) {
  DatasetSpec spec;
  spec.name = name;
  spec.set = std::move(set);
  return make_scene(spec).mesh();
}

}  // namespace

TEST(CellOverlapFast, AgreesWithTheExhaustiveSearchOnTheTestMeshes) {
  const Vec3 c{0.1, 0.1, 0.1}, in = Vec3{-1, -1, -1} * 1e-12, up{0, 0, 1e-15};
  const Vec3 a0{-1, 0, 0}, a1{1, 0, 0}, a2{0, 1, -1}, a3{0, -1, -1};
  const Vec3 b0{0, -1, 0}, b1{0, 1, 0}, b2{1, 0, 1}, b3{-1, 0, 1}, down{0, 0, -1e-13};
  const std::vector<std::pair<CellMesh, bool>> cases = {
      {tet_pair(O, X, Y, Z, X, Y, Z, {1, 1, 1}), false},
      {tet_pair(O, X, Y, Z, X, Y, {1, 1, 0}, {1, 1, -1}), false},
      {tet_pair(O, X, Y, Z, O, -X, -Y, -Z), false},
      {tet_pair(O, X, Y, Z, {0.3, 0.2, 0}, {1.3, 0.2, 0}, {0.3, 1.2, 0}, {0.3, 0.2, -1}), false},
      {tet_pair(a0, a1, a2, a3, b0, b1, b2, b3), false},
      {tet_pair(a0, a1, a2, a3, b0 + down, b1 + down, b2 + down, b3 + down), true},
      {tet_pair(O, X, Y, Z, X + in, Y + in, Z + in, Vec3{1, 1, 1} + in), true},
      {tet_pair(O, X, Y, Z, X - in, Y - in, Z - in, Vec3{1, 1, 1} - in), false},
      {tet_pair(O, X, Y, Z, {std::nextafter(1.0, 0.0), 0, 0}, Y, Z, {1, 1, 1}), true},
      {tet_pair(O, X, Y, Z, Vec3{0.3, 0.2, 0} + up, Vec3{1.3, 0.2, 0} + up, Vec3{0.3, 1.2, 0} + up,
                Vec3{0.3, 0.2, -1} + up),
       true},
      {tet_pair(O, X, Y, Z, O, X, Y, Z), true},
      // Contained: no boundary contact at all, caught by the nesting sample.
      {tet_pair(O, X, Y, Z, c, c + X * 0.1, c + Y * 0.1, c + Z * 0.1), true},
      {tet_pair(O, X, Y, Z, O + X * 2, X * 3, X * 2 + Y, X * 2 + Z), false},
      {kuhn_block(3), false},
      {kuhn_block(4, 1.0, 0.2, 7), false},
      {hex_block(3), false},
      {append(kuhn_block(2), translated(kuhn_block(2), {2, 0, 0})), false},
      {append(kuhn_block(2), translated(kuhn_block(4, 0.5), {2, 0, 0})), false},
      {append(hex_block(2), translated(hex_block(2), {0, 0, 2})), false},
      {interpenetrating_blocks(2), true},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const OverlapCertificate cert = certify(cases[i].first, "case " + std::to_string(i));
    EXPECT_EQ(cert.result, cases[i].second ? OverlapCertificate::Overlap : OverlapCertificate::Clean)
        << "case " << i;
  }
}

TEST(CellOverlapFast, BentQuadsAreLeftToTheExhaustiveSearch) {
  CellMesh lower;
  lower.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1.05}, {0, 1, 1}};
  lower.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  const OverlapCertificate c = certify(append(lower, lower), "bent");
  EXPECT_EQ(c.result, OverlapCertificate::Undecided);
  EXPECT_EQ(check_overlapping_cells(append(lower, lower), build_mesh_faces(append(lower, lower), "bent"))
                .pairs.size(),
            1u);
}

TEST(CellOverlapFast, ABlockNestedInsideAnotherWithoutContactIsCaught) {
  // A 2^3 block of side 1 inside a 4^3 block of side 4, away from its boundary and off its
  // grid planes: no boundary face of one meets a boundary face of the other.
  const CellMesh big = kuhn_block(4);
  const CellMesh m = append(big, translated(kuhn_block(2, 0.5), {1.3, 1.2, 1.1}));
  const OverlapCertificate c = certify(m, "nested");
  EXPECT_EQ(c.result, OverlapCertificate::Overlap);
  EXPECT_EQ(c.components, 2);
  EXPECT_GT(c.nesting_pairs, 0);
  EXPECT_LT(c.witness.first, int32_t(big.num_cells()));
  EXPECT_GE(c.witness.second, int32_t(big.num_cells()));
  // A block inside the other's cavity would be clean: a shell of hexahedra around a hole.
  const CellMesh cube = hex_block(3);
  CellMesh shell;
  shell.points = cube.points;
  for (size_t h = 0; h < cube.num_cells(); ++h)
    if (h != 13) shell.add_cell(cube.types[h], cube.cell_points(h));  // 13: the cavity
  const CellMesh in_cavity = append(shell, translated(kuhn_block(1, 0.5), {1.25, 1.25, 1.25}));
  EXPECT_EQ(certify(in_cavity, "cavity").result, OverlapCertificate::Clean);
  EXPECT_EQ(certify(in_cavity, "cavity").components, 2);  // the shell, the inner block
  // A block that swallows the cavity, its boundary inside the shell's cells and the
  // cavity's wall inside its cells: no boundary face meets another, and every cell's
  // centroid but the shell's near the cavity is covered once. Sampling one centroid per
  // boundary component would miss it; boundary faces inside cells do not.
  const CellMesh too_big = append(shell, translated(kuhn_block(1, 1.2), {0.9, 0.9, 0.9}));
  EXPECT_EQ(certify(too_big, "cavity").result, OverlapCertificate::Overlap);
}

TEST(CellOverlapFast, CrossingTouchingAndDuplicatedBlocks) {
  // Crossing: caught through the boundary contacts.
  const OverlapCertificate crossing = certify(
      append(kuhn_block(3), translated(kuhn_block(3, 1.0, 0.2, 5), {1.5, 0.5, -1.25})), "crossing");
  EXPECT_EQ(crossing.result, OverlapCertificate::Overlap);
  // Touching, face to face with duplicated nodes, conforming or not: clean.
  EXPECT_EQ(certify(append(kuhn_block(3), translated(kuhn_block(3), {0, 0, 3})), "touching").result,
            OverlapCertificate::Clean);
  EXPECT_EQ(certify(append(kuhn_block(3), translated(kuhn_block(2, 1.5), {0.75, 0, 3})), "shifted").result,
            OverlapCertificate::Clean);
  // A whole mesh twice: every boundary face lies on its copy, facing the same way.
  for (const CellMesh& m : {kuhn_block(3), kuhn_block(3, 1.0, 0.25, 9), hex_block(2)})
    EXPECT_EQ(certify(append(m, m), "duplicate").result, OverlapCertificate::Overlap);
}

TEST(CellOverlapFast, AgreesOnTheGeneratedDatasets) {
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> sets = {
      {"gap", {{"nx", "4"}, {"ny", "4"}, {"nz", "6"}, {"gaps", "2"}}},
      {"helix", {{"cells", "3000"}}},
      {"zoo", {}},
      {"offset", {}},
      {"slivers", {}},
      {"cycle", {}},
      {"cycle-sticks", {}},
      {"tiny", {}},
      {"touching-conforming", {}},
      {"touching-shifted", {}},
      {"touching-rotated", {}},
      {"touching-overhang", {}},
      {"touching-edge", {}},
      {"touching-hex", {}},
  };
  for (const auto& [name, set] : sets) {
    const CellMesh m = dataset(name, set);
    const OverlapCertificate c = certify(m, name);
    EXPECT_NE(c.result, OverlapCertificate::Overlap) << name;  // all are valid meshes
  }
  // The gmsh file of two boxes meshed separately over the same space.
  DatasetSpec spec;
  spec.input = std::string(VOB_TEST_DATA) + "/two_boxes.vtk";
  EXPECT_EQ(certify(make_scene(spec).mesh(), "two_boxes").result, OverlapCertificate::Overlap);
}

TEST(CellOverlapFast, AgreesOnRandomPlacementsOfTwoAndThreeBlocks) {
  // Blocks of different sizes placed at random on a coarse lattice (so that contacts,
  // coplanar faces and nesting all happen) and at random off it.
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> lattice(-4, 8);
  std::uniform_real_distribution<double> off(-1.0, 3.0);
  int overlapping = 0, clean = 0;
  for (int trial = 0; trial < 120; ++trial) {
    CellMesh m = kuhn_block(3, 1.0, trial % 3 == 0 ? 0.2 : 0.0, uint32_t(trial + 1));
    const int parts = 1 + trial % 2;
    for (int p = 0; p < parts; ++p) {
      const int kind = (trial / 2 + p) % 3;
      const CellMesh b = kind == 0 ? kuhn_block(1, 0.5) : kind == 1 ? kuhn_block(2, 0.75) : hex_block(1, 0.5);
      const Vec3 at = trial % 4 < 2 ? Vec3{lattice(rng) * 0.25, lattice(rng) * 0.25, lattice(rng) * 0.25}
                                    : Vec3{off(rng), off(rng), off(rng)};
      m = append(m, translated(b, at));
    }
    const OverlapCertificate c = certify(m, "trial " + std::to_string(trial));
    EXPECT_NE(c.result, OverlapCertificate::Undecided);
    (c.result == OverlapCertificate::Overlap ? overlapping : clean) += 1;
  }
  EXPECT_GT(overlapping, 20);
  EXPECT_GT(clean, 10);
}

// Warped quads: the oracle takes each quad as one plane (cell_planes.h), so cells sharing
// only an edge of warped quads can overlap in its model while their hulls only touch.
// `validate` applies the oracle's model to such pairs (cell_overlap.h, "Warped quads").
namespace {

CellOverlapReport validate_report(const CellMesh& m, const std::string& what) {
  validate_cell_mesh(m, what);
  return check_overlapping_cells(m, build_mesh_faces(m, what));
}

bool share_a_face(const CellMesh& m, int32_t a, int32_t b) {
  int shared = 0;
  for (int i = 0; i < m.cell_size(a); ++i)
    for (int j = 0; j < m.cell_size(b); ++j) shared += m.cell_points(a)[i] == m.cell_points(b)[j];
  return shared >= 3;
}

}  // namespace

TEST(CellOverlapWarped, TwistedHexBarOverlapsAsTheOracleModelsIt) {
  // 2 x 2 hexahedra per layer, 2 layers, each turned by 0.01 rad: around the bar's axis the
  // diagonal neighbours share only an edge, and the oracle's planes of their warped side
  // quads overlap near it.
  const CellMesh m = overlapping_twisted_bar(2, 0.01);
  const CellOverlapReport r = validate_report(m, "twisted bar");
  EXPECT_EQ(r.warped_cells, 8);
  const std::vector<std::pair<int32_t, int32_t>> expected = {{0, 3}, {4, 7}};
  EXPECT_EQ(r.pairs, expected);
  EXPECT_EQ(r.pairs.size(), r.model_pairs.size());  // no hulls interpenetrate
  const double tol = model_overlap_tolerance(m);
  EXPECT_EQ(r.model_tolerance, tol);
  for (const auto& p : r.model_pairs) {
    const auto [a, b] = p.cells;
    EXPECT_FALSE(cells_interpenetrate(m, a, b)) << a << " " << b;
    EXPECT_FALSE(share_a_face(m, a, b)) << a << " " << b;  // face neighbours meet exactly
    EXPECT_GT(p.thickness, 0.004) << a << " " << b;  // about twist / 2, far above tol
    EXPECT_LT(p.thickness, 0.006) << a << " " << b;
    const ModelOverlap o = cells_overlap_as_modelled(m, a, b, tol);
    EXPECT_TRUE(o.overlap && o.solved);
    EXPECT_EQ(o.thickness, p.thickness);
  }
  const std::string line = describe_overlap("bar.vtu", r, &m);
  EXPECT_NE(line.find("as the oracle models them"), std::string::npos) << line;
  EXPECT_NE(line.find("not planar"), std::string::npos) << line;
  EXPECT_NE(line.find("takes each quad as one plane"), std::string::npos) << line;
  const QuadWarp w = worst_quad_warp(m, r.pairs[0].first);
  EXPECT_GE(w.face, 0);
  EXPECT_GT(w.relative, 1e-3);
  EXPECT_LT(w.relative, 1e-2);
  // In the natural numbering the same bar only touches; untwisted, its quads are planar and
  // the model is not even tested.
  EXPECT_TRUE(validate_report(twisted_hex_bar(2, 2, 0.01), "twisted bar").pairs.empty());
  const CellOverlapReport flat = validate_report(overlapping_twisted_bar(2, 0.0), "straight bar");
  EXPECT_EQ(flat.warped_cells, 0);
  EXPECT_EQ(flat.model_tests, 0);
  EXPECT_TRUE(flat.pairs.empty());
}

TEST(CellOverlapWarped, QuadsPlanarOnlyToRoundingStayClean) {
  // A hex block turned about an oblique axis (gmsh's rotated box): its quads are planar
  // only up to rounding, so the model is tested and finds every overlap far below the
  // oracle's threshold (settled by the filter, no LP).
  const CellMesh m = rotated(hex_block(3), {0.3, 0.5, 0.8}, 0.651);
  const CellOverlapReport r = validate_report(m, "rotated block");
  EXPECT_GT(r.warped_cells, 0);
  EXPECT_GT(r.model_tests, 0);
  EXPECT_EQ(r.model_lps, 0);
  EXPECT_TRUE(r.pairs.empty()) << describe_overlap("rotated block", r, &m);
  // The zoo's lat-long cells likewise (the oracle check of zoo is in oracle/overlap_test).
  const CellMesh zoo = dataset("zoo");
  const CellOverlapReport z = validate_report(zoo, "zoo");
  EXPECT_GT(z.warped_cells, 0);
  EXPECT_TRUE(z.pairs.empty()) << describe_overlap("zoo", z, &zoo);
}

TEST(CellOverlapWarped, CellsSharingAWarpedQuadDoNotOverlapInTheModel) {
  // The bent quad shared by two stacked hexahedra is one plane for both (bit-identical,
  // negated): the model leaves no room for a cube on both sides.
  CellMesh lower;
  lower.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1.05}, {0, 1, 1}};
  lower.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  CellMesh m = lower;
  m.points.insert(m.points.end(), {{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
  m.add_cell(CellType::Hexahedron, {4, 5, 6, 7, 8, 9, 10, 11});
  const double tol = model_overlap_tolerance(m);
  const ModelOverlap o = cells_overlap_as_modelled(m, 0, 1, tol);
  EXPECT_FALSE(o.overlap);
  EXPECT_LE(o.thickness, 0.25 * tol);
  EXPECT_TRUE(validate_report(m, "stacked").pairs.empty());
  // Moved into each other, they overlap in either model.
  const CellMesh pushed = append(lower, translated(lower, {0, 0, 0.9}));
  const CellOverlapReport r = validate_report(pushed, "pushed");
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_TRUE(r.model_pairs.empty());  // the hulls already interpenetrate
  EXPECT_TRUE(cells_overlap_as_modelled(pushed, 0, 1, tol).overlap);
}

TEST(CellOverlapWarped, FilterBoundsTheLinearProgram) {
  // Pairs of jittered hexahedra (warped quads, touching in every way a block allows): where
  // the filter settles a pair, its bound is at least the exact LP's thickness.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.04, 0.04);
  int filtered = 0, compared = 0;
  for (int round = 0; round < 20; ++round) {
    CellMesh m = hex_block(2);
    for (Vec3& p : m.points) p += Vec3{jitter(rng), jitter(rng), jitter(rng)};
    validate_cell_mesh(m, "jittered");
    const double tol = model_overlap_tolerance(m);
    for (int32_t a = 0; a < 8; ++a)
      for (int32_t b = a + 1; b < 8; ++b) {
        const overlap_detail::ModelCell ma = overlap_detail::model_cell(m, a), mb = overlap_detail::model_cell(m, b);
        ASSERT_TRUE(ma.reliable && mb.reliable);
        const ModelOverlap f = overlap_detail::model_overlap(m, a, b, &ma, &mb, tol);
        const ModelOverlap lp = overlap_detail::model_overlap(m, a, b, nullptr, nullptr, tol);
        ASSERT_TRUE(lp.solved);
        ++compared;
        if (f.filtered) {
          ++filtered;
          EXPECT_FALSE(lp.overlap);
          EXPECT_GE(f.thickness, lp.thickness) << a << " " << b;
          EXPECT_LE(f.thickness, 0.25 * tol) << a << " " << b;
        } else {
          EXPECT_EQ(f.overlap, lp.overlap);
        }
      }
  }
  EXPECT_GT(filtered, compared / 2);
}

TEST(CellOverlapWarped, ModelBoxHoldsTheModelPolyhedron) {
  // Points inside every face half-space of the oracle's planes, sampled around each cell of
  // twisted and jittered blocks, lie in the cell's model box.
  std::mt19937 rng(11);
  const std::vector<CellMesh> meshes = {twisted_hex_bar(2, 2, 0.05), twisted_hex_bar(3, 1, 0.2),
                                        kuhn_block(2, 1.0, 0.2, 3)};
  for (const CellMesh& m : meshes) {
    for (int32_t c = 0; c < int32_t(m.num_cells()); ++c) {
      const overlap_detail::ModelCell mc = overlap_detail::model_cell(m, c);
      ASSERT_TRUE(mc.bounded);
      CellPlanes pl;
      cell_face_planes(m, c, pl);
      Aabb around;
      for (int i = 0; i < m.cell_size(c); ++i) around.add(m.points[m.cell_points(c)[i]]);
      const Vec3 mid = around.center(), half = (around.hi - around.lo) * 0.75;
      std::uniform_real_distribution<double> u(-1, 1);
      int inside = 0;
      for (int s = 0; s < 4000; ++s) {
        const Vec3 x = mid + Vec3{u(rng) * half.x, u(rng) * half.y, u(rng) * half.z};
        bool in = true;
        for (int f = 0; f < pl.count && in; ++f) in = dot(pl.n[f], x - pl.o[f]) <= 0;
        if (!in) continue;
        ++inside;
        EXPECT_TRUE(x.x >= mc.box.lo.x && x.x <= mc.box.hi.x && x.y >= mc.box.lo.y && x.y <= mc.box.hi.y &&
                    x.z >= mc.box.lo.z && x.z <= mc.box.hi.z)
            << "cell " << c;
      }
      EXPECT_GT(inside, 0);
    }
  }
}
