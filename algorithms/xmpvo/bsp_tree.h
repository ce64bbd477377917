// View-independent BSP tree of a mesh's exterior faces (Comba et al.'s BSP-XMPVO).
//
// Exterior faces are taken as triangles (a quad as (0,1,2), (0,2,3), as cell validation
// tests it). Splitting planes pass through three double points: the plane of an exterior
// triangle (autopartition), or, where no triangle plane divides the fragments well (the
// convex stretches of a curved surface, where every face plane has all the others behind
// it), a free axis-aligned plane through a median. During the build, fragments are exact
// polygons whose vertices are named by the planes they lie on and never constructed
// (bsp_fragment.h, bsp_planes.h): every decision of side is exact, settled by an interval
// filter nearly always and by exact arithmetic otherwise. The finished tree keeps doubles
// only: per node its plane and the ORIGINAL ids of the triangles whose fragments are
// coplanar with it. Traversals therefore test node planes and whole original triangles, a
// superset of the fragments, which is what a conservative candidate search needs.
//
// Items of a node are coplanar and pairwise interior-disjoint (a valid mesh's boundary), but
// there can be very many (a slab face of a gap mesh): each node with more than kLeafItems
// items keeps them in a small bounding-box hierarchy (exact min/max of double vertices), so
// that a query visits only the items near it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"
#include "harness/scene/exterior_faces.h"

namespace vob::xmpvo {

struct BspTriangle {
  Vec3 p[3];      // counter-clockwise seen from outside the mesh (normal points out)
  int32_t face;   // the MeshFaces face it comes from
  int32_t cell;   // that face's cell
};

// Axis-aligned box hierarchy over one node's items: children of inner node i are
// `left` and left + 1; leaves hold items [first, first + count) of BspTree::items.
struct ItemBox {
  Vec3 lo, hi;
  int32_t left = -1;  // -1: leaf
  int32_t first = 0, count = 0;
};

struct BspNode {
  int32_t splitter = -1;            // triangle whose plane splits, -1 for a free plane
  int32_t front = -1, back = -1;    // children: positive (normal) side, negative side; -1 none
  int32_t first = 0, count = 0;     // coplanar items: BspTree::items[first, first + count)
  int32_t boxes = -1;               // root of the node's ItemBox hierarchy, -1 when none
  Vec3 lo, hi;                      // box of the whole triangles stored in the subtree
  // The plane: orient3d(a, b, c, x) > 0 on the front side. For fast filtered signs:
  // det(b-a, c-a, w) = n.w with n = (b-a)x(c-a) in doubles, and nabs the matching sums of
  // |products|, which bound its rounding.
  Vec3 a, b, c, n, nabs;
};

struct BspOptions {
  int candidates = 5;      // splitters tried per node (best by fewest splits, then balance)
  int sample = 64;         // fragments each candidate is scored on
  int split_weight = 8;    // score = split_weight * splits + |front - back|
  bool free_planes = true; // also score an axis-aligned median plane at each node
  bool keep_fragments = false;  // keep exact fragments for check_invariants() (tests)
};

struct BspStats {
  int64_t nodes = 0, depth = 0, fragments = 0, splits = 0;
  int64_t triangles = 0;   // b in triangles (quads count twice)
  int64_t free_nodes = 0;  // nodes split by a free (median) plane
  int64_t free_refused = 0;  // free planes guessed to divide that exact sides showed did not
  // Sides of split-fragment vertices that the endpoints' signs left open: decided by the
  // interval filter, and of those by exact arithmetic.
  int64_t filtered_tests = 0, exact_tests = 0;
  int64_t point_tests = 0;  // sides of triangle vertices the double filter left to orient3d
  double growth = 0;       // fragments / triangles
  double seconds = 0;
};

class BspTree {
 public:
  static constexpr int kLeafItems = 8;

  BspTree();
  ~BspTree();
  BspTree(BspTree&&) noexcept;
  BspTree& operator=(BspTree&&) noexcept;

  // Builds the tree of the boundary faces. Deterministic. An empty boundary gives an
  // empty tree.
  static BspTree build(const ExteriorFaces& exterior, const BspOptions& opt = {});

  const std::vector<BspTriangle>& triangles() const { return tris_; }
  const std::vector<BspNode>& nodes() const { return nodes_; }
  const std::vector<int32_t>& items() const { return items_; }
  const std::vector<ItemBox>& boxes() const { return boxes_; }
  int32_t root() const { return nodes_.empty() ? -1 : 0; }
  // Whether triangle t was never split: its one fragment, at one node, is all of it.
  bool unsplit(int32_t t) const { return unsplit_[t] != 0; }
  const BspStats& stats() const { return stats_; }
  size_t bytes() const;

  // With keep_fragments: checks, exactly, that every stored fragment lies in its
  // triangle's plane and on the closed correct side of every ancestor's plane, that it sits
  // at a node coplanar with it, and that the fragments of each triangle cover it (their
  // areas, projected to the triangle's dominant axis plane, sum to its area). Returns ""
  // when all hold, else the first failure.
  std::string check_invariants() const;

 private:
  struct Exact;  // exact fragments kept for check_invariants (CGAL stays in the .cpp)
  std::vector<BspTriangle> tris_;
  std::vector<BspNode> nodes_;
  std::vector<int32_t> items_;
  std::vector<ItemBox> boxes_;
  std::vector<int32_t> parent_;  // per node, -1 at the root
  std::vector<uint8_t> unsplit_;  // per triangle
  BspStats stats_;
  std::unique_ptr<Exact> exact_;
};

}  // namespace vob::xmpvo
