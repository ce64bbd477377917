// XMPVO's "ray queries" phase. At each arrangement vertex v: the faces whose closed
// projection holds v (exact sides), split into those with v inside (sorted by exact depth
// order) and those with v on their boundary (a wedge of directions). Each sector between
// consecutive boundary directions is a region touching v; its faces are the inside ones
// plus the boundary ones covering it, in depth order. Consecutive (back-facing nearer,
// front-facing farther) pairs give "cell of the nearer in front of cell of the farther".
// Points get a full query, the crossings of each projected edge a sweep along it
// (edge_sweep.cpp); a point that a sweep ended at takes its covering faces from that
// sweep. Queries run in parallel (TBB); the relation set does not depend on the thread
// split (some counters do: a thread reuses its last sweep start and its sweeps' ends).
#pragma once
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/arrangement.h"
#include "harness/scene/exterior_faces.h"

namespace vob::xmpvo {

// What the queries read: the view's exterior faces, their projection and arrangement.
struct QueryInput {
  const Signs& signs;  // mode and view geometry
  const ExteriorFaces& ext;
  const std::vector<FacePlane>& plane;  // exact-filter planes of the exterior faces
  const Projection& proj;
  const Arrangement& arr;
  // Crossings by the edge sweep (edge_sweep.cpp) where the view allows; off: a full query
  // at every vertex (the same relations, for tests and comparisons).
  bool sweep = true;
  // The exterior surface meets itself only at shared vertices and edges (find_edge_contacts
  // found no touched edge): the sweep's swaps need no depth comparison (edge_sweep.cpp).
  bool conforming = false;
  // Projected side tests first against one bound for the whole query (vertex_query.cpp,
  // Worker::orient_raw); off: uv_side's own bound at every test (the same signs, for tests).
  bool quick_sides = true;
  // A point query after a sweep that ended at the point takes the point's strictly covering
  // faces, sorted, from that sweep (sweep_ends.cpp) instead of gathering and
  // sorting them; only on conforming surfaces whose arrangement marked the points on other
  // edges' lines. Off: every point gathers (the same relations, for tests).
  bool sweep_ends = true;
};

struct QueryStats {
  int64_t vertex_queries = 0, sectors = 0, sector_faces = 0, depth_calls = 0,
          depth_full = 0, depth_undecided = 0, degenerate = 0;
  int64_t side = 0, dis_side = 0;  // sign decisions and disagreements (compare mode)
  // Side tests the double filter decided, those it left to the exact predicate, and the
  // queries with at least one such exact re-check.
  int64_t side_filtered = 0, side_rechecked = 0, queries_rechecked = 0;
  int64_t depth_rechecked = 0;  // depth comparisons the filtered plane keys left undecided
  // Edges swept, crossings the sweeps passed (two per crossing), edges that fell back to
  // full queries; sweep depth comparisons decided by the sides of a plane alone.
  int64_t sweep_edges = 0, sweep_crossings = 0, sweep_fallbacks = 0, depth_plane_sides = 0;
  // Crossings whose entering face took the leaving face's place (edge_sweep.cpp, swap).
  int64_t sweep_swaps = 0;
  // Sweep depth comparisons of a face of the swept edge with an entering face decided by
  // the orientation of the two edges (edge_sweep.cpp, depth_edges).
  int64_t depth_edge_orders = 0;
  // Point queries that took their covering faces from a sweep ending at the point.
  int64_t sweep_end_queries = 0;
  int64_t sheet_edges_unswept = 0;  // edges left out by Arrangement::unswept_sheet
  // The view needs full queries at every vertex (no sweeps, or a degeneracy) but the
  // arrangement left out crossings (Arrangement::unswept_sheet): no relations were made;
  // build it again with 0 and ask once more (view_relations does).
  bool needs_every_crossing = false;
  int64_t arrangement_rebuilt = 0;  // view_relations built the arrangement again
  size_t scratch_bytes = 0;        // the query threads' scratch
  void add(const QueryStats& o);
};

// What the queries keep from one view to the next: the workers with their per-face tables
// and lists, the view's tables and the sweeps' edge index. Made from scratch every view,
// they were allocated and first touched again every frame (on the 200k helix interleaved
// with SXMPVO, ray queries of 103-124 ms in some frames against 86-92 in the others: the
// heap's memory handed back and faulted in again). One per orderer; one call at a time.
class QueryScratch {
 public:
  QueryScratch();
  ~QueryScratch();
  QueryScratch(QueryScratch&&) noexcept;
  QueryScratch& operator=(QueryScratch&&) noexcept;
  size_t bytes() const;
  struct Impl;
  std::unique_ptr<Impl> impl;
};

// The relation pairs (front cell, back cell), sorted and without duplicates, into `pairs`.
void run_ray_queries(const QueryInput& in, QueryStats& stats, QueryScratch& scratch,
                     std::vector<std::pair<int32_t, int32_t>>& pairs);

// run_ray_queries, and where the view needs full queries at every vertex but the
// arrangement left out crossings, the arrangement built again with none left out and the
// full queries (so a caller's ray-query time includes the second build). `candidates`
// takes the second build's count of tested edge pairs.
void view_relations(QueryInput in, Arrangement& arr, Signs& signs, QueryStats& stats, int64_t& candidates,
                    QueryScratch& scratch, std::vector<std::pair<int32_t, int32_t>>& pairs);
// The same with a scratch of its own (tests).
std::vector<std::pair<int32_t, int32_t>> view_relations(QueryInput in, Arrangement& arr, Signs& signs,
                                                        QueryStats& stats, int64_t& candidates);

}  // namespace vob::xmpvo
