// The BSP tree of exterior faces (algorithms/xmpvo/bsp_tree.h): every exterior triangle has
// a fragment, fragments sit on the closed correct side of every ancestor plane and cover
// their triangle (checked exactly on the kept fragments), unsplit triangles checked again
// here with orient3d on their own vertices; on convex, nonconvex, quad, coplanar-heavy and
// hard meshes.
#include <gtest/gtest.h>

#include <map>

#include "algorithms/xmpvo/bsp_tree.h"
#include "datasets/datasets.h"
#include "harness/geometry/predicates.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::xmpvo;
using namespace vob::testing;

namespace {

// Builds with exact fragments kept and checks the invariants; returns the tree.
BspTree check_tree(const Scene& s, BspOptions opt = {}) {
  opt.keep_fragments = true;
  BspTree t = BspTree::build(s.exterior_faces(), opt);
  const MeshFaces& f = s.faces();
  int64_t expected = 0;
  for (int32_t id : f.boundary) expected += f.face_size(id) - 2;
  EXPECT_EQ(t.stats().triangles, expected) << s.name();
  EXPECT_EQ(static_cast<int64_t>(t.triangles().size()), expected);
  EXPECT_EQ(t.check_invariants(), "") << s.name();
  EXPECT_EQ(t.stats().nodes, static_cast<int64_t>(t.nodes().size()));
  EXPECT_EQ(t.stats().fragments, static_cast<int64_t>(t.items().size()));
  EXPECT_GE(t.stats().fragments, t.stats().triangles);
  EXPECT_GE(t.stats().growth, 1.0);
  EXPECT_GT(t.stats().depth, 0);
  EXPECT_GT(t.bytes(), 0u);

  // Independent of the kept fragments: every triangle is an item somewhere; a triangle
  // stored once was never split, so its own vertices lie on the closed side of every
  // ancestor plane that leads to its node; a splitter triangle is among its node's items,
  // a free plane (splitter -1) has one child on each side.
  const auto& nodes = t.nodes();
  std::vector<int> count(t.triangles().size(), 0);
  std::vector<int32_t> at(t.triangles().size(), -1);
  std::vector<int32_t> parent(nodes.size(), -1);
  for (size_t n = 0; n < nodes.size(); ++n) {
    if (nodes[n].front >= 0) parent[nodes[n].front] = static_cast<int32_t>(n);
    if (nodes[n].back >= 0) parent[nodes[n].back] = static_cast<int32_t>(n);
    bool has_splitter = false;
    for (int32_t i = nodes[n].first; i < nodes[n].first + nodes[n].count; ++i) {
      ++count[t.items()[i]];
      at[t.items()[i]] = static_cast<int32_t>(n);
      has_splitter |= t.items()[i] == nodes[n].splitter;
    }
    if (nodes[n].splitter >= 0) {
      EXPECT_TRUE(has_splitter) << "node " << n;
      const BspTriangle& sp = t.triangles()[nodes[n].splitter];
      EXPECT_TRUE(sp.p[0] == nodes[n].a && sp.p[1] == nodes[n].b && sp.p[2] == nodes[n].c) << "node " << n;
    } else {
      EXPECT_TRUE(nodes[n].front >= 0 && nodes[n].back >= 0) << "free node " << n;
    }
  }
  int64_t unsplit = 0, wrong = 0;
  for (size_t i = 0; i < count.size(); ++i) {
    EXPECT_GE(count[i], 1) << "triangle " << i;
    EXPECT_EQ(t.unsplit(static_cast<int32_t>(i)), count[i] == 1);
    if (count[i] != 1) continue;
    ++unsplit;
    const BspTriangle& tr = t.triangles()[i];
    for (int32_t child = at[i], up = parent[at[i]]; up >= 0; child = up, up = parent[up]) {
      const BspNode& sp = nodes[up];
      const int want = sp.front == child ? 1 : -1;
      for (const Vec3& p : tr.p) wrong += orient3d(sp.a, sp.b, sp.c, p) == -want;
    }
    const BspNode& own = nodes[at[i]];
    for (const Vec3& p : tr.p) wrong += orient3d(own.a, own.b, own.c, p) != 0;
  }
  EXPECT_EQ(wrong, 0) << s.name();
  EXPECT_GT(unsplit, 0) << s.name();
  // Item boxes contain their items.
  for (const BspNode& n : nodes) {
    if (n.boxes < 0) {
      EXPECT_LE(n.count, BspTree::kLeafItems);
      continue;
    }
    const ItemBox& root = t.boxes()[n.boxes];
    EXPECT_EQ(root.first, n.first);
    EXPECT_EQ(root.count, n.count);
  }
  for (const ItemBox& b : t.boxes())
    for (int32_t i = b.first; i < b.first + b.count; ++i)
      for (const Vec3& p : t.triangles()[t.items()[i]].p)
        EXPECT_TRUE(p.x >= b.lo.x && p.y >= b.lo.y && p.z >= b.lo.z && p.x <= b.hi.x &&
                    p.y <= b.hi.y && p.z <= b.hi.z);
  return t;
}

}  // namespace

// A convex block: its exterior triangles lie in 6 planes, so every face plane is a splitter
// that splits nothing and the tree has one node per plane; large coplanar sets get boxes.
TEST(BspTree, ConvexBlockIsSixCoplanarNodes) {
  const Scene s = Scene::from_mesh("block", tet_block(4, 4, 4));
  const BspTree t = check_tree(s);
  EXPECT_EQ(t.stats().nodes, 6);
  EXPECT_EQ(t.stats().splits, 0);
  EXPECT_EQ(t.stats().growth, 1.0);
  EXPECT_FALSE(t.boxes().empty());
}

TEST(BspTree, NonconvexAndQuadMeshes) {
  check_tree(Scene::from_mesh("two-blocks", two_blocks(2, 0.5)));
  check_tree(Scene::from_mesh("blade-ring", blade_ring(8)));
  const BspTree h = check_tree(dataset("helix", {{"cells", "2000"}}));
  EXPECT_GT(h.stats().splits, 0);  // a curved tube cannot be partitioned without splits
  check_tree(dataset("zoo", {{"scale", "1"}}));
  check_tree(dataset("gap", {{"nx", "4"}, {"ny", "4"}, {"nz", "12"}, {"gaps", "5"}}));
}

// Hard inputs: near-flat slivers, coordinates offset by 1e7, the visibility-cycle meshes.
TEST(BspTree, HardCases) {
  check_tree(dataset("slivers", {}));
  check_tree(dataset("offset", {}));
  check_tree(dataset("cycle-sticks", {}));
  check_tree(dataset("cycle", {}));
}

// Other splitter choices give other trees; all must satisfy the invariants.
TEST(BspTree, SplitterChoices) {
  const Scene s = dataset("helix", {{"cells", "600"}});
  for (int c : {1, 16}) {
    BspOptions opt;
    opt.candidates = c;
    opt.sample = c == 1 ? 1 : 1000;
    check_tree(s, opt);
  }
}

// A curved tube is convex along long stretches, where every face plane has the others on
// one side: median planes (free nodes) are chosen there and make the tree shallower; without
// them the tree is an autopartition. Both satisfy the invariants.
TEST(BspTree, FreeMedianPlanesOnACurvedSurface) {
  const Scene s = dataset("helix", {{"cells", "1500"}});
  BspOptions opt;
  opt.split_weight = 2;
  const BspTree with = check_tree(s, opt);
  opt.free_planes = false;
  const BspTree without = check_tree(s, opt);
  auto free_nodes = [](const BspTree& t) {
    int64_t n = 0;
    for (const BspNode& node : t.nodes()) n += node.splitter < 0;
    return n;
  };
  EXPECT_GT(free_nodes(with), 0);
  EXPECT_EQ(free_nodes(without), 0);
  EXPECT_LT(with.stats().depth, without.stats().depth);
}

TEST(BspTree, EmptyBoundaryGivesEmptyTree) {
  const BspTree t = BspTree::build(ExteriorFaces{}, {});
  EXPECT_EQ(t.root(), -1);
  EXPECT_EQ(t.stats().nodes, 0);
}
