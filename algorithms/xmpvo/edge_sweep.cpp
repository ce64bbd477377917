// XMPVO's edge sweep: the relations along one projected edge e = (a, b) with crossings.
// Between two consecutive crossings on e the faces whose projection covers e (faces of e
// excluded) do not change, and neither does their depth order (exterior faces of a valid
// mesh do not cross), so the sweep keeps them sorted front to back in list_: taken from
// a's point query, then at each crossing with an edge e' = (c, d) the faces of e' on a's
// side leave and those on b's side enter, and the faces of e keep their positions (epos_).
// Where e' has one face on each side (about 98% of the crossings on a helix), the entering
// face takes the leaving face's place (swap()); elsewhere each entering face is placed by
// depth comparisons (cross()).
//
// What is emitted: along each open segment of e between its vertices, on each side of e,
// the consecutive pairs next to the positions of e's faces (their neighbours where they
// cover, the pair they separate where they do not). A pair that is consecutive somewhere
// stops being so across an edge of one of its faces or of a face entering between them,
// and there it is such a pair of that edge: so the sweeps of all edges with crossings and
// the full queries at the points find exactly the pairs the full queries at every
// arrangement vertex find (the segments next to a and b also touch a and b). Crossings
// themselves get no query.
//
// One sheet's inner edges need no sweep (Arrangement::unswept_sheet, on conforming
// surfaces): an edge whose two faces lie on either side of it and both face the same way.
// Only pairs (b, f) of a back face b and a front face f behind it are emitted (emit()).
// Across such an edge of a third face, that face gives way to its neighbour at the same
// depth, so the pair stays consecutive: the region where (b, f) is consecutive is bounded
// by edges of b, edges of f and silhouette edges (one-sided: a face entering or leaving
// between them). Leave out the front sheet's inner edges: b's edges and the silhouettes are
// still swept, so a region with any of them on its boundary is found there; a region
// bounded by f's inner edges alone is all of f, and the queries at f's points find it.
// (Leaving out both sheets would lose regions bounded by inner edges of b and f alone.) So
// the relations are the same. A crossing of two such edges is then read by no sweep, and
// the arrangement does not look for it.
//
// Depth at a crossing: an entering face g holds e', so the crossing's ray meets g's plane
// on the segment (c, d). Where c and d lie strictly on one side of a face h's plane
// (orient3d, filtered), so does that point, and g is in front of h exactly when that is
// the eye's side; otherwise the crossing's ray and plane keys decide (depth()).
//
// Premises, each checked, else every crossing on e gets a full query (pairs rolled back):
// no point lies on the projected boundary of a face it is not a vertex of (the point
// queries watch for it, for the whole view: run_ray_queries); the crossings on e are
// certainly ordered (their boxes' extents along e are disjoint, which also rules out
// three edges through one point); a leaving face is in list_; no depth comparison is
// undecided. All signs are the exact ones (filtered as in full queries).
//
// A sweep that decided every crossing leaves in list_ the faces covering e's last segment;
// but those having b as a vertex, they are b's strictly covering faces in depth order, which
// b's own query then takes instead of gathering them (sweep_ends.cpp).
#include <algorithm>
#include <cmath>
#include <immintrin.h>

#include "algorithms/xmpvo/query_worker.h"
#include "algorithms/xmpvo/uv_filter.h"
#include "harness/cpu_features.h"
#include "harness/geometry/predicates.h"

namespace vob::xmpvo::detail {

namespace {
// first_of_two in AVX-512 lanes: the first 32 places in two compares each with no branch
// (most lists hold 5 to 17 faces, unpredictably either side of 16), the rest sixteen a step.
__attribute__((target("avx512f,avx512vl,avx512dq,avx2"))) void first_of_two_avx512(
    const int32_t* l, int32_t n, int32_t g0, int32_t g1, int32_t& i0, int32_t& i1) {
  if (n <= 0) {  // l may be null: no l + 16
    i0 = i1 = n;
    return;
  }
  const __m512i v0 = _mm512_set1_epi32(g0), v1 = _mm512_set1_epi32(g1);
  const unsigned in0 = (1u << std::min(n, 16)) - 1, in1 = (1u << std::clamp(n - 16, 0, 16)) - 1;
  const __m512i x0 = _mm512_maskz_loadu_epi32(static_cast<__mmask16>(in0), l);
  const __m512i x1 = _mm512_maskz_loadu_epi32(static_cast<__mmask16>(in1), l + 16);
  const uint32_t m0 = _mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(in0), x0, v0) |
                      uint32_t(_mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(in1), x1, v0)) << 16;
  const uint32_t m1 = _mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(in0), x0, v1) |
                      uint32_t(_mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(in1), x1, v1)) << 16;
  int32_t f0 = m0 ? __builtin_ctz(m0) : n, f1 = m1 ? __builtin_ctz(m1) : n;
  for (int32_t j = 32; j < n; j += 16) {
    const __mmask16 valid = static_cast<__mmask16>((1u << std::min(n - j, 16)) - 1);
    const __m512i x = _mm512_maskz_loadu_epi32(valid, l + j);
    const unsigned k0 = _mm512_mask_cmpeq_epi32_mask(valid, x, v0), k1 = _mm512_mask_cmpeq_epi32_mask(valid, x, v1);
    f0 = std::min(f0, k0 ? j + __builtin_ctz(k0) : n);
    f1 = std::min(f1, k1 ? j + __builtin_ctz(k1) : n);
  }
  i0 = f0, i1 = f1;
}
}  // namespace

// Both in one pass with no jump on the faces: where std::find stopped was a coin toss, a
// mispredicted exit per search. In lanes: the 200k helix's ray queries at view 0 about 3%
// faster (the scalar loop was about 40% of the sweep's samples), and 3.5% more with the
// first 32 places in two compares instead of a loop of sixteen a step.
void first_of_two(const int32_t* l, int32_t n, int32_t g0, int32_t g1, int32_t& i0, int32_t& i1, bool lanes) {
  static const bool avx512 = cpu_has_avx512();
  if (lanes && avx512) return first_of_two_avx512(l, n, g0, g1, i0, i1);
  i0 = n, i1 = n;
  for (int32_t j = n - 1; j >= 0; --j) {
    i0 = l[j] == g0 ? j : i0;
    i1 = l[j] == g1 ? j : i1;
  }
}

void Worker::sweep_edge(int32_t e) {
  const Arrangement& arr = in_->arr;
  // Without crossings the regions along e touch a and b: the point queries see them.
  if (arr.unswept(e)) {  // an inner edge of the sheet left out (Arrangement::unswept_sheet)
    ++stats_.sheet_edges_unswept;
    return;
  }
  if (arr.edge_vertex_off[e] == arr.edge_vertex_off[e + 1]) return;
  ++stats_.sweep_edges;
  const size_t mark = pairs_.size();
  const int64_t answered = stats_.sweep_crossings;
  rechecked_ = false;
  const int32_t x0 = arr.edge_vertex_off[e];
  sort_edge_crossings(&arr.edge_crossings[x0], arr.edge_vertex_off[e + 1] - x0, xings_);
  const bool ok = sweep(e);
  stats_.queries_rechecked += rechecked_;
  if (ok) {
    keep_end_list(e);
    return;
  }
  pairs_.resize(mark);
  std::fill(seen_.begin(), seen_.end(), 0);
  stats_.sweep_crossings = answered;
  ++stats_.sweep_fallbacks;
  for (const EdgeCrossing& xing : xings_) query(xing.vertex);
}

bool Worker::sweep(int32_t e) {
  undecided_ = false;
  swept_ = e;
  if (!order_crossings() || !start_list(e)) return false;
  emit_segment();
  const size_t nx = xings_.size();
  for (size_t ix = 0; ix < nx; ++ix) {
    const EdgeCrossing& xing = xings_[ix];
    // swap() reads the crossed edge's faces first, from a table indexed at random: asked
    // for four crossings ahead.
    if (ix + 4 < nx) __builtin_prefetch(&in_->arr.swap_faces(xings_[ix + 4].other));
    // Nearly every crossing of a conforming surface is a swap, which reads neither depths
    // nor the crossed edge's points (a random read): tried here, inline.
    if (!(in_->conforming && swap(e, xing)) && !cross(e, xing)) return false;
    // The pairs next to e's faces change only where a face leaves or enters beside them.
    if (beside_) emit_segment();
  }
  return !undecided_;
}

// Whether the swept edge's crossings (xings_, sorted by key) are certainly in order from a
// to b: their extents along the edge are disjoint.
bool Worker::order_crossings() const {
  for (size_t x = 1; x < xings_.size(); ++x)
    if (!(xings_[x - 1].key + xings_[x - 1].ext < xings_[x].key - xings_[x].ext)) return false;
  return true;
}

// list_ just after a along e: the faces covering a's neighbourhood, and the faces with a
// as a corner whose angle holds the direction of b strictly; sorted at a's ray. The faces
// of e: their positions, the side of e they cover, their order where on one side.
bool Worker::start_list(int32_t e) {
  const auto [a, b] = in_->arr.edges[e];
  const int32_t va = view_->point_vertex[a];
  if (va < 0) return false;
  if (vi_ != va) begin(va);  // the same context, and its plane keys stay valid
  const ArrVertex& v = *current_;
  // The sweeps from a follow a's point query, which left its sorted covering faces (unless
  // undecided; a sweep's fallback queries leave them too).
  if (start_point_ != a) {
    gather(v);
    sort_inside();
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
  const Arrangement& arr = in_->arr;
  n_eface_ = 0;
  for (int32_t x = arr.edge_face_off[e]; x < arr.edge_face_off[e + 1]; ++x) {
    if (n_eface_ == 4) return false;
    const int32_t f = arr.edge_faces[x];
    const int dir = arr.edge_face_dir[x];
    eface_[n_eface_] = f;
    eside_[n_eface_] = static_cast<int8_t>(dir * -in_->proj.facing[f]);
    epos_[n_eface_++] = static_cast<int32_t>(insert_at(f));
  }
  // Faces of e on one side (a fold of the surface) keep their depth order along e.
  for (int i = 0; i < n_eface_; ++i)
    for (int j = 0; j < n_eface_; ++j)
      ebefore_[i][j] = i != j && eside_[i] == eside_[j] && depth(eface_[i], eface_[j]) < 0;
  return !undecided_;
}

// Crossing `xing` of e with e' = (c, d): the faces of e' leave or enter list_ (on a
// conforming surface sweep() has tried swap() first). The faces of e keep their positions
// in list_ (epos_); an entering face goes where the leaving face of the same edge was when
// its neighbours confirm it, else by binary search.
bool Worker::cross(int32_t e, const EdgeCrossing& xing) {
  const Arrangement& arr = in_->arr;
  const int32_t other = xing.other;
  const auto [c, d] = arr.edges[other];
  xvi_ = xing.vertex, xc_pt_ = c, xd_pt_ = d, n_psign_ = 0;
  if (!in_->conforming && swap(e, xing)) return true;
  const int32_t a = arr.edges[e].first;
  const int sa = point_side(a, c, d);
  if (sa == 0) return false;
  xsa_ = sa;
  int32_t enter[8], leave_at = -1;
  int n_enter = 0, n_leave = 0;
  beside_ = false;
  for (int32_t x = arr.edge_face_off[other]; x < arr.edge_face_off[other + 1]; ++x) {
    const int32_t g = arr.edge_faces[x];
    const int dir = arr.edge_face_dir[x];
    if (sa * dir * -in_->proj.facing[g] > 0) {
      const auto it = std::find(list_.begin(), list_.end(), g);
      if (it == list_.end()) return false;
      const int32_t i = static_cast<int32_t>(it - list_.begin());
      for (int k = 0; k < n_eface_; ++k) beside_ |= i == epos_[k] - 1 || i == epos_[k];
      list_.erase(it);
      for (int k = 0; k < n_eface_; ++k) epos_[k] -= i < epos_[k];
      leave_at = i, ++n_leave;
    } else {
      if (n_enter == 8) return false;
      enter[n_enter++] = g;
    }
  }
  const bool simple = n_leave <= 1 && n_enter <= 1;
  for (int k = 0; k < n_enter; ++k) {
    const size_t j = simple && n_leave == 1 ? place(enter[k], leave_at) : insert_at_crossing(enter[k]);
    for (int m = 0; m < n_eface_; ++m) beside_ |= static_cast<int32_t>(j) == epos_[m];
    for (int m = 0; m < n_eface_; ++m) epos_[m] = track(enter[k], m, static_cast<int32_t>(j));
    list_.insert(list_.begin() + static_cast<std::ptrdiff_t>(j), enter[k]);
  }
  ++stats_.sweep_crossings;
  return !undecided_;
}

// Crossing `xing` of e with e' = (c, d) when e' has one face on each side (not a silhouette
// edge: about 98% of the crossings on the 200k helix): the face of e' that covers the
// segment before the crossing leaves, its neighbour across e' enters, and the two meet
// the crossing's ray at the same point of (c, d), so the entering face takes the leaving
// face's place unless another face h of list_ holds that point: h would lie at the same
// depth there, and might be on the other side of the entering face. On a conforming
// surface (no exterior face meets an exterior edge it does not have: in_->conforming, from
// find_edge_contacts) no face does, so the place is exact with no depth comparison;
// otherwise its neighbours in list_ confirm it (place()'s test). Where a face of e is its
// neighbour, the rays meet e and e' at distinct points (orient3d(c, d, a, b) != 0), so that
// face keeps its side of it. On a conforming surface that needs no test: the two edges
// cross properly in projection, so coplanar they would meet in space, and each would meet
// the other's faces. Returns false, with list_ unchanged, wherever the general path
// must decide instead (which face leaves unknown, a neighbour not confirming).
inline bool Worker::swap(int32_t e, const EdgeCrossing& xing) {
  const Arrangement& arr = in_->arr;
  const auto [g0, g1] = arr.swap_faces(xing.other);
  if (g0 < 0) return false;
  // Where g0 and g1 are in list_ (n: not there).
  const int32_t n = static_cast<int32_t>(list_.size());
  int32_t i0, i1;
  first_of_two(list_.data(), n, g0, g1, i0, i1);
  if ((i0 == n) == (i1 == n)) return false;
  const bool first_leaves = i0 != n;
  const int32_t i = first_leaves ? i0 : i1;
  const int32_t enter = first_leaves ? g1 : g0;
  if (!in_->conforming && ((i > 0 && depth_x(enter, list_[i - 1]) <= 0) || (i + 1 < n && depth_x(enter, list_[i + 1]) >= 0))) {
    undecided_ = false;  // depth_x's undecided answers are the general path's to give
    return false;
  }
  bool beside = false;
  for (int k = 0; k < n_eface_; ++k) beside |= i == epos_[k] - 1 || i == epos_[k];
  if (beside && !in_->conforming) {
    const auto [a, b] = arr.edges[e];
    const auto [c, d] = arr.edges[xing.other];
    if (orient3d(pt(c), pt(d), pt(a), pt(b)) == 0) return false;
  }
  list_[static_cast<size_t>(i)] = enter;
  beside_ = beside;
  ++stats_.sweep_crossings;
  ++stats_.sweep_swaps;
  return true;
}

// The pairs next to the faces of e along the current segment, on each side of e.
void Worker::emit_segment() {
  const int32_t n = static_cast<int32_t>(list_.size());
  for (int i = 0; i < n_eface_; ++i) {
    const int32_t p = epos_[i];
    // Faces of e on this face's side at the same position: the nearest in front, behind.
    int fj = -1, bj = -1;
    for (int j = 0; j < n_eface_; ++j) {
      if (j == i || eside_[j] != eside_[i] || epos_[j] != p) continue;
      if (ebefore_[j][i] && (fj < 0 || ebefore_[fj][j])) fj = j;
      if (ebefore_[i][j] && (bj < 0 || ebefore_[j][bj])) bj = j;
    }
    const int32_t front = fj >= 0 ? eface_[fj] : p > 0 ? list_[p - 1] : -1;
    const int32_t back = bj >= 0 ? eface_[bj] : p < n ? list_[p] : -1;
    if (front >= 0) emit(front, eface_[i]);
    if (back >= 0) emit(eface_[i], back);
    // The pair it separates on the other side, unless a face of e is there too.
    if (p == 0 || p == n) continue;
    bool other_here = false;
    for (int j = 0; j < n_eface_; ++j) other_here |= eside_[j] != eside_[i] && epos_[j] == p;
    if (!other_here) emit(list_[p - 1], list_[p]);
  }
}

// Where entering face f goes in list_: at `guess` when its neighbours there confirm it,
// else by binary search.
size_t Worker::place(int32_t f, int32_t guess) {
  const size_t j = static_cast<size_t>(guess);
  if ((j == 0 || depth_x(f, list_[j - 1]) > 0) && (j == list_.size() || depth_x(f, list_[j]) < 0)) return j;
  return insert_at_crossing(f);
}

// A face of e at position pos after face f enters list_ at j.
int32_t Worker::track(int32_t f, int m, int32_t j) {
  const int32_t pos = epos_[m];
  if (j != pos) return pos + (j < pos);
  return pos + (depth_edges(f, m) < 0);
}

// Depth order of face g of e' = (c, d) and face m of e = (a, b) at the crossing: the
// crossing's ray meets them on the edges, at Q on (c, d) and P on (a, b). With Q = E + mu
// (P - E) (E the eye; for orthographic views its limit at infinity along -dir) and
// orient3d affine in each point, orient3d(c, d, a, b) has the sign of (1 - mu) orient3d(c,
// d, a, E), where orient3d(c, d, a, E) = -orient3d(E, c, d, a) has the sign -sa of the
// crossing (cross()): so P is nearer (b's face in front) exactly when orient3d(c, d, a, b)
// has the sign -sa. Zero (the edges meet in space): the faces touch on the ray, depth_x.
int Worker::depth_edges(int32_t g, int m) {
  const auto [a, b] = in_->arr.edges[swept_];
  const int o = orient3d(pt(xc_pt_), pt(xd_pt_), pt(a), pt(b));
  if (o == 0) return depth_x(g, eface_[m]);
  ++stats_.depth_edge_orders;
  return o == -xsa_ ? 1 : -1;
}

// Where face f of e' goes in list_ (front to back) at the current crossing.
size_t Worker::insert_at_crossing(int32_t f) {
  return size_t(std::partition_point(list_.begin(), list_.end(), [&](int32_t h) { return depth_x(f, h) >= 0; }) -
                list_.begin());
}

// Depth order of face g of e' and face h covering the crossing, on the crossing's ray:
// from the sides of c and d to h's plane when they agree, else from the ray's keys.
int Worker::depth_x(int32_t g, int32_t h) {
  int k = 0;
  while (k < n_psign_ && psign_face_[k] != h) ++k;
  if (k == n_psign_) {
    const int sc = plane_side(h, xc_pt_);
    const int sd = sc == 0 ? 0 : plane_side(h, xd_pt_);
    k = n_psign_ < kPsign ? n_psign_++ : 0;
    psign_face_[k] = h;
    psign_[k] = static_cast<int8_t>(sc == sd ? sc : 0);
  }
  if (psign_[k] != 0) {
    ++stats_.depth_plane_sides;
    return psign_[k] == in_->proj.facing[h] ? -1 : 1;
  }
  if (vi_ != xvi_) begin(xvi_);
  return depth(g, h);
}

// Side of point p to face h's plane (orient3d of its first three vertices), filtered; 0
// for h's own vertices when the filter cannot tell (on the plane, or a quadrilateral's
// fourth: depth() decides).
int Worker::plane_side(int32_t h, int32_t p) {
  // Neighbouring crossings on an edge share points (a strip of faces crosses it): memo.
  const uint64_t key = (uint64_t(uint32_t(h)) << 32 | uint32_t(p)) + 1;
  const size_t slot = (key * 0x9E3779B97F4A7C15ull) >> (64 - kPlaneMemoBits);
  if (plane_memo_key_[slot] == key) return plane_memo_sign_[slot];
  const int r = plane_side_raw(h, p);
  plane_memo_key_[slot] = key;
  plane_memo_sign_[slot] = static_cast<int8_t>(r);
  return r;
}

int Worker::plane_side_raw(int32_t h, int32_t p) {
  const FacePlane& f = in_->plane[h];
  const Vec3& q = pt(p);
  const Fd s = Fd{f.n[0][0], f.n[0][1]} * (Fd{q.x, 0} - Fd{f.f[0].x, 0}) +
               Fd{f.n[1][0], f.n[1][1]} * (Fd{q.y, 0} - Fd{f.f[0].y, 0}) +
               Fd{f.n[2][0], f.n[2][1]} * (Fd{q.z, 0} - Fd{f.f[0].z, 0});
  const int r = fd_sign(s);
  if (r != 2) return r;
  const int32_t* hv = &in_->ext.vertex[4 * h];
  if (hv[0] == p || hv[1] == p || hv[2] == p || (in_->ext.size[h] > 3 && hv[3] == p)) return 0;
  ++stats_.depth_rechecked;
  rechecked_ = true;
  return orient3d(f.f[0], f.f[1], f.f[2], q);
}

// Sign of D(x, p, q) for a projected point x, as orient_at gives it at a point vertex.
int Worker::point_side(int32_t x, int32_t p, int32_t q) {
  const Projection& pr = in_->proj;
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
  return size_t(std::partition_point(list_.begin(), list_.end(), [&](int32_t h) { return depth(f, h) >= 0; }) -
                list_.begin());
}

}  // namespace vob::xmpvo::detail
