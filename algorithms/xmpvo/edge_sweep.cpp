// XMPVO's edge sweep: the ray queries of the crossings on one projected edge e = (a, b),
// sharing their covering faces. Between two consecutive crossings on e the faces whose
// projection covers e (faces of e excluded) do not change, and neither does their depth
// order (exterior faces of a valid mesh do not cross), so the sweep keeps them sorted
// front to back in list_: found and sorted once at a by a full query, then at each
// crossing with an edge e' the faces of e' on a's side leave and those on b's side enter
// (one binary search each). At a crossing e owns (its first edge) the inside faces are
// list_ after the leaving ones, the boundary faces those of e and e', and the relations
// follow as in a full query (emit_sectors).
//
// Premises, each checked, else the edge's crossings get full queries (pairs rolled back):
// no point lies on the projected boundary of a face it is not a vertex of (the point
// queries watch for it, for the whole view: run_ray_queries); the crossings on e are
// certainly ordered (their boxes' extents along e are disjoint, which also rules out
// three edges through one point); every face of e and e' meets the crossing in one edge;
// a leaving face is in list_; no depth comparison is undecided. All signs are the exact
// ones (filtered as in full queries), so the relations are those of the full queries.
#include <algorithm>
#include <cmath>

#include "algorithms/xmpvo/query_worker.h"
#include "algorithms/xmpvo/uv_filter.h"

namespace vob::xmpvo::detail {

void Worker::sweep_edge(int32_t e) {
  const Arrangement& arr = in_.arr;
  bool owns = false;
  for (int32_t x = arr.edge_vertex_off[e]; x < arr.edge_vertex_off[e + 1] && !owns; ++x)
    owns = arr.vertices[arr.edge_vertices[x]].e1 == e;
  if (!owns) return;
  ++stats_.sweep_edges;
  const size_t mark = pairs_.size();
  const int64_t answered = stats_.sweep_crossings;
  rechecked_ = false;
  const bool ok = sweep(e);
  stats_.queries_rechecked += rechecked_;
  if (ok) return;
  pairs_.resize(mark);
  std::fill(seen_.begin(), seen_.end(), 0);
  stats_.sweep_crossings = answered;
  ++stats_.sweep_fallbacks;
  for (int32_t x = arr.edge_vertex_off[e]; x < arr.edge_vertex_off[e + 1]; ++x)
    if (arr.vertices[arr.edge_vertices[x]].e1 == e) query(arr.edge_vertices[x]);
}

bool Worker::sweep(int32_t e) {
  undecided_ = false;
  if (!order_crossings(e) || !start_list(e)) return false;
  for (int32_t vi : order_)
    if (!cross(e, vi)) return false;
  return !undecided_;
}

// The crossings on e from a to b, when their order is certain: each exact crossing lies
// in its vertex box, so its position along e (a dot product with e's projected direction,
// monotone along the exact edge) lies within the box's extent, widened by the rounding.
bool Worker::order_crossings(int32_t e) {
  const Arrangement& arr = in_.arr;
  const auto [ax, ay] = in_.proj.uv[arr.edges[e].first];
  const auto [bx, by] = in_.proj.uv[arr.edges[e].second];
  const double dx = bx - ax, dy = by - ay;
  keys_.clear();
  for (int32_t x = arr.edge_vertex_off[e]; x < arr.edge_vertex_off[e + 1]; ++x) {
    const Box& b = arr.vertices[arr.edge_vertices[x]].box;
    keys_.push_back({dx * (0.5 * (b.x0 + b.x1) - ax) + dy * (0.5 * (b.y0 + b.y1) - ay), arr.edge_vertices[x]});
  }
  std::sort(keys_.begin(), keys_.end());
  auto extent = [&](int32_t vi) {
    const Box& b = arr.vertices[vi].box;
    const double xc = 0.5 * (b.x0 + b.x1), yc = 0.5 * (b.y0 + b.y1);
    return std::fabs(dx) * (0.5 * (b.x1 - b.x0)) + std::fabs(dy) * (0.5 * (b.y1 - b.y0)) +
           1e-14 * (std::fabs(dx) * (std::fabs(xc) + std::fabs(ax)) + std::fabs(dy) * (std::fabs(yc) + std::fabs(ay))) +
           1e-300;
  };
  order_.clear();
  for (size_t k = 0; k < keys_.size(); ++k) {
    if (k > 0 && !(keys_[k - 1].first + extent(keys_[k - 1].second) < keys_[k].first - extent(keys_[k].second)))
      return false;
    order_.push_back(keys_[k].second);
  }
  return true;
}

// list_ just after a along e: the faces covering a's neighbourhood, and the faces with a
// as a corner whose angle holds the direction of b strictly; sorted at a's ray.
bool Worker::start_list(int32_t e) {
  const auto [a, b] = in_.arr.edges[e];
  const int32_t va = point_vertex_[a];
  if (va < 0) return false;
  begin(va);
  const ArrVertex& v = *current_;
  // Edges are numbered by their first point, so consecutive sweeps mostly start at the
  // same point: its covering faces are found and sorted once.
  if (start_point_ != a) {
    start_point_ = -1;
    gather(v);
    sort_inside(v);
    start_inside_ = inside_;
    start_wedges_ = wedges_;
    if (!undecided_) start_point_ = a;  // else this sweep falls back, the next recomputes
  }
  list_ = start_inside_;
  for (const Wedge& w : start_wedges_) {
    if (w.s == b || w.t == b) continue;  // a face of e
    if (w.half) return false;
    // The angle is below 180 degrees: outside it when either side is negative (b along
    // the opposite of s or t, as on a straight grid line, included); b along s or t
    // itself (a point on the other's edge) is left to the full queries.
    const int os = orient_at(v, w.s, b), ot = orient_at(v, b, w.t);
    if (os < 0 || ot < 0) continue;
    if (os == 0 || ot == 0) return false;
    list_.insert(list_.begin() + static_cast<std::ptrdiff_t>(insert_at(w.face)), w.face);
  }
  const Arrangement& arr = in_.arr;
  n_eface_ = 0;
  for (int32_t x = arr.edge_face_off[e]; x < arr.edge_face_off[e + 1]; ++x) {
    if (n_eface_ == 4) return false;
    eface_[n_eface_] = arr.edge_faces[x];
    epos_[n_eface_++] = static_cast<int32_t>(insert_at(arr.edge_faces[x]));
  }
  return true;
}

// Crossing vi of e with e': the faces of e' leave or enter list_; at a crossing e owns,
// the relations of the full query at vi. The faces of e keep their positions in list_
// (epos_), a leaving face's position is where it was, an entering face's where the
// leaving face of the same edge was when its neighbours confirm it (the ray through the
// crossing meets both faces' planes at one point of e'), else a binary search.
bool Worker::cross(int32_t e, int32_t vi) {
  const Arrangement& arr = in_.arr;
  begin(vi);
  memo_ = true;
  const ArrVertex& v = *current_;
  const int32_t other = v.e1 == e ? v.e2 : v.e1;
  const auto [c, d] = arr.edges[other];
  const int32_t a = arr.edges[e].first;
  const int sa = point_side(a, c, d);
  if (sa == 0) return false;
  int32_t enter[8], leave_face = -1, leave_at = -1;
  int n_enter = 0, n_leave = 0;
  for (int32_t x = arr.edge_face_off[other]; x < arr.edge_face_off[other + 1]; ++x) {
    const int32_t g = arr.edge_faces[x];
    const int32_t* p = &in_.ext.vertex[4 * g];
    const int n = in_.ext.size[g];
    int dir = 0;  // +1: g has the directed edge c -> d, -1: d -> c
    for (int k = 0; k < n; ++k) {
      const int32_t p0 = p[k], p1 = p[k + 1 < n ? k + 1 : 0];
      if (p0 == c && p1 == d) dir = 1;
      if (p0 == d && p1 == c) dir = -1;
    }
    if (dir == 0) return false;
    if (sa * dir * -in_.proj.facing[g] > 0) {
      const auto it = std::find(list_.begin(), list_.end(), g);
      if (it == list_.end()) return false;
      const int32_t i = static_cast<int32_t>(it - list_.begin());
      list_.erase(it);
      for (int k = 0; k < n_eface_; ++k) epos_[k] -= i < epos_[k];
      leave_face = g, leave_at = i, ++n_leave;
    } else {
      if (n_enter == 8) return false;
      enter[n_enter++] = g;
    }
  }
  const bool simple = n_leave <= 1 && n_enter <= 1;
  size_t at = 0;
  if (simple && n_enter == 1) at = n_leave == 1 ? place(enter[0], leave_at) : insert_at(enter[0]);
  if (v.e1 == e) {
    inside_ = list_;
    wedges_.clear();
    for (int32_t edge : {e, other})
      for (int32_t x = arr.edge_face_off[edge]; x < arr.edge_face_off[edge + 1]; ++x) {
        const size_t before = wedges_.size();
        const int32_t g = arr.edge_faces[x];
        if (!edge_wedge(g, edge == e ? arr.edges[e] : arr.edges[other])) classify(v, g);
        if (wedges_.size() != before + 1 || !wedges_.back().half) return false;
        Wedge& w = wedges_.back();
        w.pos = edge == e ? epos_[x - arr.edge_face_off[edge]]
                : g == leave_face ? leave_at : static_cast<int32_t>(at);
      }
    emit_sectors(v, simple);
    ++stats_.sweep_crossings;
  }
  for (int k = 0; k < n_enter; ++k) {
    const size_t j = simple ? at : insert_at(enter[k]);
    for (int m = 0; m < n_eface_; ++m) epos_[m] = track(enter[k], m, static_cast<int32_t>(j));
    list_.insert(list_.begin() + static_cast<std::ptrdiff_t>(j), enter[k]);
  }
  return !undecided_;
}

// Where entering face f goes in list_: at `guess` when its neighbours there confirm it,
// else by binary search.
size_t Worker::place(int32_t f, int32_t guess) {
  const size_t j = static_cast<size_t>(guess);
  if ((j == 0 || depth(f, list_[j - 1]) > 0) && (j == list_.size() || depth(f, list_[j]) < 0)) return j;
  return insert_at(f);
}

// A face of e at position pos after face f enters list_ at j.
int32_t Worker::track(int32_t f, int m, int32_t j) {
  const int32_t pos = epos_[m];
  if (j != pos) return pos + (j < pos);
  return pos + (depth(f, eface_[m]) < 0);
}

// A triangle with the crossing inside its edge (p, q): the wedge classify would find
// without testing its other sides, which hold the open edge strictly (a projected
// triangle that is not edge-on has no zero-length height). Quadrilaterals are classified.
bool Worker::edge_wedge(int32_t f, std::pair<int32_t, int32_t> pq) {
  if (in_.ext.size[f] != 3) return false;
  const int32_t* p = &in_.ext.vertex[4 * f];
  for (int k = 0; k < 3; ++k) {
    const int32_t a = p[k], b = p[k + 1 < 3 ? k + 1 : 0];
    if (!((a == pq.first && b == pq.second) || (a == pq.second && b == pq.first))) continue;
    const int inner = -in_.proj.facing[f];
    wedges_.push_back({f, inner > 0 ? b : a, inner > 0 ? a : b, p[(k + 2) % 3], true, 0});
    return true;
  }
  return false;
}

// Sign of D(x, p, q) for a projected point x, as orient_at gives it at a point vertex.
int Worker::point_side(int32_t x, int32_t p, int32_t q) {
  const Projection& pr = in_.proj;
  if (filter_) {
    const int s = uv_side(pr.uv[x], pr.uv[p], pr.uv[q], pr.slack);
    if (s != 2) {
      ++stats_.side_filtered;
      return pr.sign_n * s;
    }
    ++stats_.side_rechecked;
    rechecked_ = true;
  }
  return signs_.edge_side(pt(x), pt(p), pt(q));
}

// Where face f goes in list_ (front to back) at the current vertex's ray.
size_t Worker::insert_at(int32_t f) {
  size_t lo = 0, hi = list_.size();
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (depth(f, list_[mid]) < 0) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}

}  // namespace vob::xmpvo::detail
