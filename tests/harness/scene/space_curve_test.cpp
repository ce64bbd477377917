// Renumbering along a space-filling curve (harness/scene/space_curve.h): the cell order is a
// permutation in curve order, points are numbered by first use, and the renumbered mesh is
// the input mesh cell for cell (same types, same points in the same vertex order).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <numeric>
#include <random>
#include <utility>

#include "harness/scene/space_curve.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::test;

namespace {
// Cell c of `r.mesh` is input cell r.input_cell[c] with the same type and vertex positions.
void expect_same_cells(const CellMesh& in, const RenumberedMesh& r) {
  ASSERT_EQ(r.mesh.num_cells(), in.num_cells());
  ASSERT_EQ(r.mesh.num_points(), in.num_points());
  for (size_t c = 0; c < in.num_cells(); ++c) {
    const int32_t old = r.input_cell[c];
    ASSERT_EQ(r.mesh.types[c], in.types[old]);
    ASSERT_EQ(r.mesh.cell_size(c), in.cell_size(old));
    for (int k = 0; k < in.cell_size(old); ++k) {
      const int32_t p = r.mesh.cell_points(c)[k];
      EXPECT_EQ(r.input_point[p], in.cell_points(old)[k]);
      EXPECT_EQ(r.mesh.points[p], in.points[in.cell_points(old)[k]]);
      EXPECT_EQ(r.mesh.scalar(p), in.scalar(in.cell_points(old)[k]));
    }
  }
}
}  // namespace

TEST(SpaceCurve, MortonCodeInterleavesAxes) {
  Aabb box;
  box.add({0, 0, 0});
  box.add({1, 1, 1});
  EXPECT_EQ(morton_code({0, 0, 0}, box), 0u);
  EXPECT_EQ(morton_code({1, 1, 1}, box), (uint64_t(1) << 63) - 1);
  // The top bit of each axis lands at bits 60 (x), 61 (y), 62 (z).
  EXPECT_EQ(morton_code({0.75, 0, 0}, box) >> 60, 1u);
  EXPECT_EQ(morton_code({0, 0.75, 0}, box) >> 60, 2u);
  EXPECT_EQ(morton_code({0, 0, 0.75}, box) >> 60, 4u);
  Aabb flat;  // a flat axis maps to 0
  flat.add({0, 0, 5});
  flat.add({1, 1, 5});
  EXPECT_EQ(morton_code({0, 0, 5}, flat), 0u);
}

// Codes pinned to those of the branching transform that preceded the masked one (Skilling's,
// as first written), so that a renumbered mesh keeps its numbering across the rewrite.
TEST(SpaceCurve, HilbertCodesOfTheBranchingTransform) {
  const Aabb box{{-1, -2, 0}, {3, 2, 1}};
  const std::pair<Vec3, uint64_t> known[] = {
      {{-1, -2, 0}, 0ull},
      {{3, 2, 1}, 6588122883467697005ull},
      {{0.1, 0.2, 0.3}, 3537283967566627552ull},
      {{2.9, -1.7, 0.05}, 9216323097680823015ull},
      {{1, 0, 0.5}, 823515360433462125ull},
      {{-0.3, 1.9, 0.99}, 2690287290474476054ull},
  };
  for (const auto& [p, code] : known) EXPECT_EQ(hilbert_code(p, box), code) << p.x << " " << p.y << " " << p.z;
}

TEST(SpaceCurve, CellOrderIsAPermutationInCurveOrder) {
  const CellMesh m = tet_block(5, 4, 3);
  const Aabb box = m.bounds();
  for (Curve curve : {Curve::Morton, Curve::Hilbert}) {
    const std::vector<int32_t> order = curve_cell_order(m, curve);
    EXPECT_TRUE(is_permutation_of(order, m.num_cells()));
    auto code = [&](int32_t c) {
      return curve == Curve::Hilbert ? hilbert_code(m.cell_centroid(c), box) : morton_code(m.cell_centroid(c), box);
    };
    for (size_t i = 1; i < order.size(); ++i) {
      const uint64_t a = code(order[i - 1]), b = code(order[i]);
      EXPECT_TRUE(a < b || (a == b && order[i - 1] < order[i])) << i;
    }
  }
}

// The centres of an 8^3 grid sorted by Hilbert code: a path through face-adjacent cells
// that visits each once (the curve's defining property), starting at the origin corner.
TEST(SpaceCurve, HilbertStepsBetweenFaceNeighbours) {
  Aabb box;
  box.add({0, 0, 0});
  box.add({8, 8, 8});
  std::vector<std::pair<uint64_t, std::array<int, 3>>> cells;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k) cells.push_back({hilbert_code({i + 0.5, j + 0.5, k + 0.5}, box), {i, j, k}});
  std::sort(cells.begin(), cells.end());
  EXPECT_EQ(cells.front().second, (std::array<int, 3>{0, 0, 0}));
  for (size_t n = 1; n < cells.size(); ++n) {
    EXPECT_NE(cells[n].first, cells[n - 1].first);
    int steps = 0;
    for (int a = 0; a < 3; ++a) steps += std::abs(cells[n].second[a] - cells[n - 1].second[a]);
    EXPECT_EQ(steps, 1) << n;
  }
}

TEST(SpaceCurve, RenumberedMeshIsTheInputCellForCellWithPointsByFirstUse) {
  CellMesh m = kuhn_block(4, 1.0, 0.2, 3);
  m.points.push_back({9, 9, 9});  // a point no cell uses: kept, after the used ones
  m.scalars.push_back(0.5);
  const RenumberedMesh r = renumber_along_curve(m);
  EXPECT_TRUE(is_permutation_of(r.input_cell, m.num_cells()));
  EXPECT_TRUE(is_permutation_of(r.input_point, m.num_points()));
  expect_same_cells(m, r);
  EXPECT_EQ(r.input_point.back(), static_cast<int32_t>(m.num_points() - 1));
  // First use: scanning the new connectivity, each new point id is at most one past the
  // largest seen so far.
  int32_t next = 0;
  for (int32_t p : r.mesh.conn) {
    EXPECT_LE(p, next);
    next = std::max(next, p + 1);
  }
  EXPECT_GT(r.bytes(), r.mesh.bytes());  // the id maps too
}

TEST(SpaceCurve, PermuteMeshAppliesBothOrdersAndRejectsNonPermutations) {
  const CellMesh m = hex_block(3);
  std::vector<int32_t> cells(m.num_cells()), points(m.num_points());
  std::iota(cells.rbegin(), cells.rend(), 0);  // reversed
  std::iota(points.rbegin(), points.rend(), 0);
  const CellMesh p = permute_mesh(m, cells, points);
  ASSERT_EQ(p.num_cells(), m.num_cells());
  for (size_t c = 0; c < m.num_cells(); ++c)
    for (int k = 0; k < m.cell_size(cells[c]); ++k)
      EXPECT_EQ(p.points[p.cell_points(c)[k]], m.points[m.cell_points(cells[c])[k]]);
  EXPECT_EQ(p.points.front(), m.points.back());
  cells[0] = cells[1];
  EXPECT_THROW(permute_mesh(m, cells, points), std::invalid_argument);
  EXPECT_THROW(permute_cells(m, {0}), std::invalid_argument);
}

// far_reuse_fraction (with near = 1024 cells, for a test-sized mesh): a block numbered slab
// by slab (a point's users at most one 600-cell slab apart) has no far reuse; shuffled, a
// point's ~20 users lie about 3,000 apart, mostly far; the curve's order of it has few again.
TEST(SpaceCurve, FarReuseFractionSeparatesCoherentFromScatteredNumbering) {
  const CellMesh m = tet_block(10, 10, 100);  // 60,000 tets
  constexpr int32_t kNear = 1024;
  EXPECT_EQ(far_reuse_fraction(m, {}, kNear), 0.0);
  std::vector<int32_t> scattered(m.num_cells());
  std::iota(scattered.begin(), scattered.end(), 0);
  std::shuffle(scattered.begin(), scattered.end(), std::mt19937(5));  // a mesher's disorder
  std::vector<int32_t> points(m.num_points());
  std::iota(points.begin(), points.end(), 0);
  const CellMesh s = permute_mesh(m, scattered, points);
  const double far_scattered = far_reuse_fraction(s, {}, kNear);
  EXPECT_GT(far_scattered, 0.5);
  EXPECT_DOUBLE_EQ(far_reuse_fraction(m, scattered, kNear), far_scattered);  // the same numbering
  EXPECT_LT(far_reuse_fraction(s, curve_cell_order(s, Curve::Hilbert), kNear), 0.2);
  EXPECT_LT(far_reuse_fraction(s, {}), far_scattered);  // the default near (kNearCells) is larger
  EXPECT_THROW(far_reuse_fraction(m, {0, 1}), std::invalid_argument);
}
