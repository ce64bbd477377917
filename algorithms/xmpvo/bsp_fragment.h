// Fragments of exterior triangles during the BSP build: convex polygons whose vertices are
// named by planes (bsp_planes.h), never constructed, so that every side decision is exact
// and nearly always settled by an interval filter.
//
// Internal to bsp_tree.cpp.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "algorithms/xmpvo/bsp_planes.h"
#include "algorithms/xmpvo/bsp_tree.h"

namespace vob::xmpvo::bsp {

// Labels of the lines a fragment's edges lie on: a plane id (>= 0), or edge k of the
// fragment's own triangle as edge_label(k) (edge k runs from vertex k to vertex k + 1).
constexpr int32_t edge_label(int k) { return -1 - k; }

// A fragment vertex: what point it is (fixed when made) and the label of the edge to the
// next vertex (changes when a split shortens that edge).
struct FVert {
  int8_t at = -1;     // the triangle's vertex `at`
  int8_t edge = -1;   // else, with at < 0: the point where triangle edge `edge` meets plane pa
  int32_t pa = -1;    // with at < 0 and edge < 0: the triangle's plane meets planes pa and pb
  int32_t pb = -1;
  int32_t out = 0;    // label of the edge to the next vertex
  IBox box;           // interval box of edge and meet points
};

// A fragment of triangle `tri`: the whole triangle until its first split.
struct Frag {
  int32_t tri = -1;
  bool whole = true;
  std::vector<FVert> poly;  // only when !whole
};

enum Side { kCoplanar, kFront, kBack, kSplit };

class FragmentOps {
 public:
  // Triangle i's plane must be plane i of `planes`; vid[3 i + k] is the id (in [0,
  // points)) of triangle i's vertex k, so that a vertex's side of a plane is found once.
  FragmentOps(const std::vector<BspTriangle>& tris, const std::vector<int32_t>& vid, int32_t points,
              const PlaneTable& planes)
      : tris_(tris), vid_(vid), planes_(planes), memo_(points, ~0u) {}

  // Sides of the fragment's vertices against plane h, in s (resized); returns the vertex
  // count. A fragment of a triangle on one closed side of h is on that side.
  int classify(int32_t h, const Frag& f, std::vector<int>& s) const;
  // Whether every vertex is on h (kCoplanar), all on one closed side, or on both.
  static Side side_of(const int* s, int n);
  // A guess of side_of(classify(...)) for scoring splitters: exact where classify needs
  // neither the filter nor exact arithmetic, else plain doubles at the middles of the
  // vertices' boxes, and a vertex too close to h to call counts as a split when it could
  // make one. No interval arithmetic, no exact arithmetic.
  Side approx_side(int32_t h, const Frag& f, std::vector<int>& s) const;
  // The fragment's vertices, approximately (a split vertex at the middle of its box),
  // appended to out: the points guess_side takes.
  void approx_points(const Frag& f, std::vector<Vec3>& out) const;
  // A guess of the side of h from those points, in plain doubles; where a point is too
  // close to h to call, exact sides of the triangle's vertices as known_sides uses them,
  // then approx_side.
  Side guess_side(int32_t h, const Frag& f, const Vec3* pts, std::vector<int>& s) const;
  // Vertex sides of split fragments decided by the interval filter, and by exact arithmetic.
  int64_t filtered_tests() const { return filtered_; }
  int64_t exact_tests() const { return exact_; }
  // Splits a fragment with vertices strictly on both sides of h (s from classify).
  void split(int32_t h, const Frag& f, const int* s, int n, Frag& front, Frag& back) const;
  // The fragment's vertices as exact points (for tests: constructions in CGAL's Epeck).
  std::vector<CGAL::Epeck::Point_3> exact_polygon(const Frag& f) const;

 private:
  int side(int32_t h, int32_t tri, int k) const;
  int known_sides(int32_t h, const Frag& f, std::vector<int>& s, bool& pending) const;
  static std::vector<FVert> whole_poly();
  FVert crossing(int32_t tri, int32_t label, int32_t h) const;  // inside RoundUp

  const std::vector<BspTriangle>& tris_;
  const std::vector<int32_t>& vid_;
  const PlaneTable& planes_;
  // Per point: the tag of the plane its side was last found for, and that side, as
  // tag << 2 | side + 1 (tags stay below PlaneTable::kMaxTag); ~0u for none.
  mutable std::vector<uint32_t> memo_;
  // Exact sides orient3d had to decide, by (plane tag << 32 | point).
  mutable std::unordered_map<uint64_t, int8_t> exact_memo_;
  mutable int64_t filtered_ = 0, exact_ = 0;
};

}  // namespace vob::xmpvo::bsp
