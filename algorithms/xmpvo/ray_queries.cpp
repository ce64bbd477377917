// The views' driver of XMPVO's ray queries: the queries and sweeps of a view run in parallel
// over the arrangement's vertices (vertex_query.cpp, edge_sweep.cpp), their relation pairs
// merged; the storage kept from view to view (QueryScratch).
#include "algorithms/xmpvo/ray_queries.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/xmpvo/query_worker.h"

namespace vob::xmpvo {

void QueryStats::add(const QueryStats& x) {
  vertex_queries += x.vertex_queries, sectors += x.sectors, sector_faces += x.sector_faces;
  depth_calls += x.depth_calls, depth_full += x.depth_full;
  depth_undecided += x.depth_undecided, degenerate += x.degenerate;
  side += x.side, dis_side += x.dis_side;
  side_filtered += x.side_filtered, side_rechecked += x.side_rechecked;
  queries_rechecked += x.queries_rechecked, depth_rechecked += x.depth_rechecked;
  sweep_edges += x.sweep_edges, sweep_crossings += x.sweep_crossings;
  sweep_fallbacks += x.sweep_fallbacks, depth_plane_sides += x.depth_plane_sides;
  sweep_swaps += x.sweep_swaps, depth_edge_orders += x.depth_edge_orders;
  sweep_end_queries += x.sweep_end_queries, sheet_edges_unswept += x.sheet_edges_unswept;
  arrangement_rebuilt += x.arrangement_rebuilt;
  scratch_bytes += x.scratch_bytes;
}

struct QueryScratch::Impl {
  detail::ViewTables view;
  tbb::enumerable_thread_specific<detail::Worker> workers;
  int64_t serial = 0;  // views run so far: a worker bound to another is started afresh
  std::vector<int32_t> edge_off, edge_ids, fill;  // the sweeps' edges by their first point
  mpvo::PairSortScratch sort;
};

QueryScratch::QueryScratch() : impl(std::make_unique<Impl>()) {}
QueryScratch::~QueryScratch() = default;
QueryScratch::QueryScratch(QueryScratch&&) noexcept = default;
QueryScratch& QueryScratch::operator=(QueryScratch&&) noexcept = default;

size_t QueryScratch::bytes() const {
  const Impl& s = *impl;
  size_t n = (s.view.point_vertex.capacity() + s.view.facing_cell.capacity() + s.view.point_face_off.capacity() +
              s.view.point_faces.capacity() + s.edge_off.capacity() + s.edge_ids.capacity() + s.fill.capacity()) *
                 sizeof(int32_t) +
             s.view.view_plane.capacity() * sizeof(ViewPlane) + s.sort.bytes();
  for (const detail::Worker& w : s.workers) n += w.bytes();
  return n;
}

void run_ray_queries(const QueryInput& in, QueryStats& stats, QueryScratch& scratch,
                     std::vector<std::pair<int32_t, int32_t>>& pairs) {
  using detail::Worker;
  // Queries are independent: threads take runs of vertices (or edges); the relation set,
  // sorted and deduplicated, does not depend on the split.
  const Arrangement& arr = in.arr;
  QueryScratch::Impl& s = *scratch.impl;
  const int64_t serial = ++s.serial;
  detail::ViewTables& view = s.view;
  view.view_plane.resize(in.plane.size());
  view.facing_cell.assign(in.ext.face.size(), 0);
  view.widest_face = 0;
  view.point_face_off.clear(), view.point_faces.clear();
  for (int32_t f : in.proj.kept) {
    view.view_plane[f] = ViewPlane::of(in.signs.g, in.plane[f]);
    view.facing_cell[f] = in.proj.facing[f] * (in.ext.cell[f] + 1);
    // NaN boxes never overlap a vertex box: not counted.
    const Box& b = in.proj.face_box[f];
    view.widest_face = std::max({view.widest_face, b.x1 - b.x0, b.y1 - b.y0});
  }
  std::vector<int32_t>& point_vertex = view.point_vertex;
  point_vertex.assign(in.ext.points.size(), -1);
  for (size_t v = 0; v < arr.projected_vertices; ++v) point_vertex[arr.vertices[v].a] = static_cast<int32_t>(v);
  // The kept faces around each point, for the queries that follow a sweep ending there.
  const bool sweep = in.sweep && in.signs.mode == Mode::Exact;
  if (sweep && in.sweep_ends && in.conforming && arr.lines_marked) detail::index_point_faces(in, view);
  // This thread's worker, bound to this view.
  auto local = [&]() -> Worker& {
    Worker& w = s.workers.local();
    if (w.view_serial_ != serial) w.start_view(in, view), w.view_serial_ = serial;
    return w;
  };
  auto queries = [&](size_t v0, size_t v1) {
    tbb::parallel_for(tbb::blocked_range<size_t>(v0, v1, 512), [&](const tbb::blocked_range<size_t>& r) {
      Worker& w = local();
      for (size_t v = r.begin(); v < r.end(); ++v) w.query(static_cast<int32_t>(v));
    });
  };
  bool degenerate = false;
  if (sweep) {
    // Each point's query, then the sweeps of the edges starting there (CSR by point vertex;
    // an edge whose first point has none is swept last, and falls back to full queries).
    const size_t np = arr.projected_vertices;
    std::vector<int32_t> &edge_off = s.edge_off, &edge_ids = s.edge_ids, &fill = s.fill;
    edge_off.assign(np + 2, 0);
    edge_ids.resize(arr.edges.size());
    auto slot = [&](size_t e) {
      const int32_t va = point_vertex[arr.edges[e].first];
      return va < 0 ? np : static_cast<size_t>(va);
    };
    for (size_t e = 0; e < arr.edges.size(); ++e) ++edge_off[slot(e) + 1];
    for (size_t v = 0; v <= np; ++v) edge_off[v + 1] += edge_off[v];
    fill.assign(edge_off.begin(), edge_off.end() - 1);
    for (size_t e = 0; e < arr.edges.size(); ++e) edge_ids[fill[slot(e)]++] = static_cast<int32_t>(e);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, np, 256), [&](const tbb::blocked_range<size_t>& r) {
      Worker& w = local();
      for (size_t v = r.begin(); v < r.end(); ++v)
        w.query_and_sweep(static_cast<int32_t>(v), &edge_ids[edge_off[v]], &edge_ids[edge_off[v + 1]]);
    });
    for (int32_t x = edge_off[np]; x < edge_off[np + 1]; ++x) local().sweep_edge(edge_ids[x]);
    // A point on another face's projected boundary, which the sweeps cannot see: the
    // view is answered by full queries instead.
    for (const Worker& w : s.workers) degenerate |= w.view_serial_ == serial && w.degenerate_seen_;
    if (degenerate)
      for (Worker& w : s.workers)
        if (w.view_serial_ == serial) w.reset();
  }
  if (!sweep || degenerate) {
    if (arr.unswept_sheet != 0) {  // crossings left out: the caller builds again
      stats = QueryStats{};
      stats.needs_every_crossing = true;
      pairs.clear();
      return;
    }
    queries(0, arr.vertices.size());
  }
  pairs.clear();
  stats = QueryStats{};
  for (Worker& w : s.workers) {
    if (w.view_serial_ != serial) continue;  // no work for this view
    pairs.insert(pairs.end(), w.pairs_.begin(), w.pairs_.end());
    w.stats_.side = w.signs_.side;
    w.stats_.dis_side = w.signs_.dis_side;
    w.stats_.scratch_bytes = w.bytes();
    stats.add(w.stats_);
  }
  int32_t last = -1;  // the largest cell id
  for (const auto& [front, behind] : pairs) last = std::max({last, front, behind});
  mpvo::sort_unique_pairs(pairs, static_cast<size_t>(last + 1), s.sort);
}

void view_relations(QueryInput in, Arrangement& arr, Signs& signs, QueryStats& stats, int64_t& candidates,
                    QueryScratch& scratch, std::vector<std::pair<int32_t, int32_t>>& pairs) {
  if (&in.arr != &arr) throw std::logic_error("xmpvo::view_relations: QueryInput of another arrangement");
  run_ray_queries(in, stats, scratch, pairs);
  if (!stats.needs_every_crossing) return;
  arr.unswept_sheet = 0;
  candidates = arr.build(in.ext, in.proj, signs);
  in.sweep = false;
  run_ray_queries(in, stats, scratch, pairs);
  stats.arrangement_rebuilt = 1;
}

std::vector<std::pair<int32_t, int32_t>> view_relations(QueryInput in, Arrangement& arr, Signs& signs,
                                                        QueryStats& stats, int64_t& candidates) {
  QueryScratch scratch;
  std::vector<std::pair<int32_t, int32_t>> pairs;
  view_relations(in, arr, signs, stats, candidates, scratch, pairs);
  return pairs;
}

}  // namespace vob::xmpvo
