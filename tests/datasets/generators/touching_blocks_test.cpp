// The touching-* hard cases (datasets/generators/touching_blocks.h): blocks that share no
// vertex, each pair separated by a plane they both touch, so their interiors are disjoint
// and touching; the interfaces are exactly coplanar (also after the rotation).
#include <algorithm>
#include <numeric>

#include "harness/geometry/predicates.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {

// Blocks = connected components of cells through shared point ids.
std::vector<int> block_of_cell(const CellMesh& m, int& blocks) {
  std::vector<int> parent(m.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int32_t* p = m.cell_points(c);
    for (int k = 1; k < cell_vertex_count(m.types[c]); ++k) parent[find(p[k])] = find(p[0]);
  }
  std::vector<int> label(m.points.size(), -1), out(m.num_cells());
  blocks = 0;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    int& l = label[find(m.cell_points(c)[0])];
    if (l < 0) l = blocks++;
    out[c] = l;
  }
  return out;
}

struct Box3 {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(Vec3 p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
};

}  // namespace

TEST(TouchingBlocks, BlocksAreDisjointAndTouch) {
  const std::vector<std::pair<const char*, int>> cases = {
      {"touching-conforming", 2}, {"touching-shifted", 2}, {"touching-rotated", 2},
      {"touching-overhang", 2},   {"touching-edge", 3},    {"touching-hex", 2}};
  for (const auto& [name, expected_blocks] : cases) {
    const Scene s = make(name);
    const CellMesh& m = s.mesh();
    int blocks = 0;
    const std::vector<int> block = block_of_cell(m, blocks);
    ASSERT_EQ(blocks, expected_blocks) << name;
    std::vector<Box3> cell_box(m.num_cells());
    for (size_t c = 0; c < m.num_cells(); ++c)
      for (int k = 0; k < cell_vertex_count(m.types[c]); ++k) cell_box[c].add(m.points[m.cell_points(c)[k]]);
    // Every pair of cells of different blocks is separated by an axis plane (interiors
    // disjoint), and every pair of blocks has cells whose closed boxes meet (they touch).
    std::vector<int> touching(blocks * blocks, 0);
    for (size_t a = 0; a < m.num_cells(); ++a)
      for (size_t b = a + 1; b < m.num_cells(); ++b) {
        if (block[a] == block[b]) continue;
        const Box3 &x = cell_box[a], &y = cell_box[b];
        bool separated = false, meet = true;
        for (int k = 0; k < 3; ++k) {
          separated |= x.hi[k] <= y.lo[k] || y.hi[k] <= x.lo[k];
          meet &= x.hi[k] >= y.lo[k] && y.hi[k] >= x.lo[k];
        }
        ASSERT_TRUE(separated) << name << ": cells " << a << " and " << b << " may overlap";
        if (meet) ++touching[block[a] * blocks + block[b]], ++touching[block[b] * blocks + block[a]];
      }
    for (int i = 0; i < blocks; ++i)
      for (int j = i + 1; j < blocks; ++j) EXPECT_GT(touching[i * blocks + j], 0) << name << " blocks " << i << ", " << j;
  }
}

TEST(TouchingBlocks, RotatedInterfaceIsExactlyPlanarAndRotated) {
  const Scene s = make("touching-rotated", {{"n", "4"}, {"angle", "11"}});
  const CellMesh& m = s.mesh();
  // Upper block: points 75.. (5 * 5 * 3 per block); its bottom layer at z = 2 exactly,
  // and not on the lower block's grid.
  const size_t per_block = 5 * 5 * 3;
  ASSERT_EQ(m.points.size(), 2 * per_block);
  int off_grid = 0;
  for (size_t i = per_block; i < per_block + 25; ++i) {
    EXPECT_EQ(m.points[i].z, 2.0);
    off_grid += m.points[i].x != std::floor(m.points[i].x);
  }
  EXPECT_GT(off_grid, 20);
  EXPECT_EQ(orient3d(m.points[per_block], m.points[per_block + 1], m.points[per_block + 5], m.points[per_block + 24]), 0);
}

TEST(TouchingBlocks, ParametersAreChecked) {
  EXPECT_THROW(make("touching-shifted", {{"n", "0"}}), InputError);
  EXPECT_THROW(make("touching-rotated", {{"angle", "200"}}), InputError);
  EXPECT_THROW(make("touching-hex", {{"angle", "3"}}), InputError);
}
