// XMPVO's "arrangement vertices" phase: the projected vertices of the kept exterior faces
// plus the proper crossings of their projected edges, found among edge pairs sharing a
// bucket (exact crossing test).
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/projection.h"
#include "harness/sort/radix_sort.h"

namespace vob::xmpvo {

// An arrangement vertex: a projected boundary point (b < 0), or the proper crossing of the
// projected edges (a, b) and (c, d). Ids are compact exterior point ids.
struct ArrVertex {
  int32_t a, b, c, d;
  double t;  // crossing: approximate parameter along (a, b), for depth keys only
  Box box;   // where its exact position lies, in projected doubles
  int32_t e1 = -1, e2 = -1;  // crossing: the edge ids of (a, b) and (c, d)
};

// A crossing as one of its edges sees it: where it lies along that edge (the vertex box's
// centre and its extent, both projected on the edge's direction from its first point),
// the vertex and the other edge. Stored per edge side by side for the edge sweep, which
// takes them sorted by key (sort_edge_crossings). 24 bytes: at 810k crossings a view (the
// 200k helix) the lists are written and read once each, so their size is their time.
struct EdgeCrossing {
  double key, ext;
  int32_t vertex, other;
};

// One edge's n crossings p[0, n) sorted by key into `out`, equal keys in their order in p,
// or in reverse when p's first key exceeds its last (edge_crossings.cpp). The sweep sorts
// each edge's list as it takes it up: the list is then read from memory once.
void sort_edge_crossings(const EdgeCrossing* p, int32_t n, std::vector<EdgeCrossing>& out);

struct Arrangement {
  std::vector<std::pair<int32_t, int32_t>> edges;  // unique projected edges
  std::vector<int32_t> edge_off, edge_items;       // edges per bucket (CSR)
  std::vector<ArrVertex> vertices;                 // points first, then crossings
  size_t projected_vertices = 0;
  // Per edge (CSR): its kept faces (with the direction each has the edge in: +1 first ->
  // second), and the crossings on it (either role; unsorted).
  std::vector<int32_t> edge_face_off, edge_faces, edge_vertex_off;
  std::vector<int8_t> edge_face_dir;
  std::vector<EdgeCrossing> edge_crossings;
  // Candidate pairs the double filter decided, and those it left to the exact test.
  int64_t crossings_filtered = 0, crossings_rechecked = 0;
  // Per exterior point: 1 where an exact re-check of a pair that does not cross properly
  // found the point on the other edge's projected line (it may lie on that edge: a point
  // on a face's boundary it is not a vertex of). Such a point's query gathers its faces in
  // full (vertex_query.cpp). Marked only when `lines_marked` (exact signs behind the double
  // filter); otherwise no point's query may rely on it.
  std::vector<uint8_t> point_on_line;
  bool lines_marked = false;
  // The pair loop's first pass and double filter four pairs a step in AVX2 lanes where the
  // CPU has them (the same answers: tests compare the two).
  bool lanes = true;
  // Where the CPU has AVX-512 too: both passes at once, eight pairs a step (the same
  // answers: tests compare it with the other two).
  bool lanes_avx512 = true;
  // The sheet whose inner edges the sweeps leave out (edge_sweep.cpp; +1 front, -1 back, 0
  // none), set before build(): an edge with two kept faces on either side of it, both
  // facing this way. Such edges get no crossing lists, and a pair of two of them is not
  // tested (no sweep would read its crossing), so `vertices` then lacks those crossings:
  // full queries at every vertex need a build with 0.
  int unswept_sheet = 0;

  // The unique edges of all of ext's faces, once per mesh (prepare): a view's edges are
  // those of its kept faces, the same lists filtered (no sort per view).
  void set_faces(const ExteriorFaces& ext);
  // Returns the number of candidate edge pairs tested. After set_faces(ext).
  int64_t build(const ExteriorFaces& ext, const Projection& proj, Signs& signs);
  size_t bytes() const;
  // Edge e's two faces when it has one on each side (else -1: a silhouette edge, or not
  // two kept faces), for the sweep's swaps. After build().
  const std::array<int32_t, 2>& swap_faces(int32_t e) const { return swap_[e]; }
  // Whether edge e is an inner edge of the unswept sheet. After build().
  bool unswept(int32_t e) const { return unswept_[e] != 0; }
  // The edges' buckets. After build().
  const BucketGrid& grid() const { return grid_; }
  // A pair is tested in the bucket of its boxes' common lower corner. A corner within this
  // fraction of a bucket's width (height) of the bucket's left (lower) side is placed by
  // the grid's col() and row(); one further in is the bucket's without asking.
  static constexpr double kSideBand = 1e-9;

 private:
  // set_faces' edge lists (as edges, edge_face_off, edge_faces, edge_face_dir) for every
  // face, and whether the per-view lists hold them unfiltered now.
  std::vector<std::pair<int32_t, int32_t>> all_edges_;
  std::vector<int32_t> all_face_off_, all_faces_;
  std::vector<int8_t> all_face_dir_;
  const ExteriorFaces* faces_of_ = nullptr;
  bool lists_are_all_ = false;
  std::vector<Box> box_;  // per edge, its projected box
  std::vector<std::array<int32_t, 2>> swap_;  // per edge, swap_faces()
  std::vector<uint8_t> unswept_;              // per edge, unswept()
  BucketGrid grid_;       // of the edges
  // The edges by their boxes' left sides (build()), with the sort's keys and buffers.
  std::vector<int32_t> by_left_;
  std::vector<double> left_key_;
  Radix64Scratch left_sort_;
  Box edge_box(const Projection& proj, int32_t e) const;
  void build_edges(const ExteriorFaces& ext, const Projection& proj);
  void mark_edges(const Projection& proj);  // swap_ and unswept_
  void index_crossings(const Projection& proj);
  // point_on_line for the four points of a pair that does not cross properly.
  [[gnu::noinline, gnu::cold]] void mark_on_line(const ViewGeometry& g, const std::vector<Vec3>& points, int32_t a,
                                                 int32_t b, int32_t c, int32_t d);
};

}  // namespace vob::xmpvo
