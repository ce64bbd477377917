// XMPVO's ray-query worker (internal to ray_queries.cpp, vertex_query.cpp and
// edge_sweep.cpp): one thread's share of the queries, with its own scratch, counters and
// relation pairs; the per-view input is read only. A full query (vertex_query.cpp) finds
// and sorts the faces covering one vertex; the edge sweep (edge_sweep.cpp) carries the
// sorted covering faces along one projected edge from crossing to crossing.
#pragma once
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/plane_keys.h"
#include "algorithms/xmpvo/ray_queries.h"

namespace vob::xmpvo::detail {

// A face with the query vertex on its projected boundary: it covers the directions from
// ray s counter-clockwise (in the sign convention of D) to ray t; a half-plane when the
// vertex is inside an edge, then `ref` is a face vertex strictly inside it.
// Bit 0: the face with points p (n of them) holds the vertex (a point) or the edge (a, b);
// bit 1: the edge (c, d). Faces that touch meet the vertex's ray at the same point.
uint8_t touch_bits(const ArrVertex& v, const int32_t* p, int n);

struct Wedge {
  int32_t face, s, t, ref;
  bool half;
  int32_t pos;  // number of inside faces in front of it
};

// Where faces g0 and g1 first occur in l[0, n), n where one does not (edge_sweep.cpp's
// swaps); `lanes`: in AVX-512 lanes where the CPU has them (the same answers).
void first_of_two(const int32_t* l, int32_t n, int32_t g0, int32_t g1, int32_t& i0, int32_t& i1, bool lanes = true);

// What every worker reads of a view besides QueryInput, made once per view
// (run_ray_queries).
struct ViewTables {
  std::vector<ViewPlane> view_plane;   // per exterior face
  std::vector<int32_t> point_vertex;   // per exterior point, its vertex id or -1
  // Per exterior face: its cell + 1 when front-facing, -(cell + 1) when back-facing, 0
  // when not kept: emit()'s test in one read.
  std::vector<int32_t> facing_cell;
  // Per projected point (its vertex id; CSR): the kept faces it is a vertex of. Empty when
  // no point query takes its covering faces from a sweep.
  std::vector<int32_t> point_face_off, point_faces;
  double widest_face = 0;  // largest side of a kept face's box (face_box)
};

// view.point_face_off and point_faces from the kept faces (sweep_ends.cpp).
void index_point_faces(const QueryInput& in, ViewTables& view);

class Worker {
 public:
  // A worker keeps its scratch from one view to the next (ray_queries.h's QueryScratch):
  // start_view() binds it to a view and resets its state, keeping the storage, so a frame
  // neither allocates nor faults in the per-face tables again.
  Worker() = default;
  void start_view(const QueryInput& in, const ViewTables& view);
  // The view start_view() last bound (QueryScratch's count of views).
  int64_t view_serial_ = -1;
  size_t bytes() const {
    return (inside_.capacity() + rays_.capacity() + sector_.capacity() + face_stamp_.capacity() + hits_.capacity() +
            key_stamp_.capacity() + touch_stamp_.capacity() + list_.capacity() + start_inside_.capacity() +
            wedge_ray_.capacity()) * 4 + ray_side_.capacity() + before_.capacity() +
           start_wedges_.capacity() * sizeof(Wedge) + plane_memo_key_.capacity() * 9 +
           touch_.capacity() + key_.capacity() * sizeof(PlaneKey) + keys_.capacity() * 16 +
           wedges_.capacity() * sizeof(Wedge) + xings_.capacity() * sizeof(EdgeCrossing) +
           (ended_at_.capacity() + ended_.capacity()) * 4 +
           (pairs_.capacity() + seen_.capacity()) * 8;
  }
  void query(int32_t vi) {
    rechecked_ = false;
    run_query(vi);
    stats_.queries_rechecked += rechecked_;
  }
  // The relations along edge e by the sweep (edges with crossings); any case the sweep
  // cannot decide (edge_sweep.cpp) falls back to full queries of the edge's crossings.
  void sweep_edge(int32_t e);

  // The full query of point vertex vi, then the sweeps of edges [e0, e1) (those starting
  // at that point), from its sorted covering faces while they are at hand. The
  // sweeps are skipped once this worker has seen a degeneracy (the view is then answered
  // by full queries: run_ray_queries).
  void query_and_sweep(int32_t vi, const int32_t* e0, const int32_t* e1);
  // Forget the pairs and counts so far (a degenerate view starts over with full queries).
  void reset();

  QueryStats stats_;
  Signs signs_;
  std::vector<std::pair<int32_t, int32_t>> pairs_;
  // A point vertex lies on the projected boundary of a face it is not a vertex of, or a
  // face meets a vertex degenerately: the sweep's premises fail for this view.
  bool degenerate_seen_ = false;

 private:
  void run_query(int32_t vi);
  // Point vertex vi's query from the covering faces a sweep ending there kept (ended_).
  void run_query_after_sweep(int32_t vi);
  void keep_end_list(int32_t e);
  void emit_at_point(const ArrVertex& v);
  void begin(int32_t vi);
  void gather(const ArrVertex& v);
  void emit_sectors(const ArrVertex& v);
  int orient_at(const ArrVertex& v, int32_t p, int32_t q);
  int orient_raw(const ArrVertex& v, int32_t p, int32_t q);
  int orient_filtered(const ArrVertex& v, int32_t p, int32_t q);
  int depth(int32_t x, int32_t y);
  void emit(int32_t nearer, int32_t farther);
  bool before(int32_t x, int32_t y);
  void classify(const ArrVertex& v, int32_t f);
  void sort_inside();
  const Vec3& pt(int32_t p) const { return in_->ext.points[p]; }
  // Edge sweep (edge_sweep.cpp).
  bool sweep(int32_t e);
  bool start_list(int32_t e);
  bool order_crossings() const;
  bool cross(int32_t e, const EdgeCrossing& xing);
  bool swap(int32_t e, const EdgeCrossing& xing);
  void emit_segment();
  int point_side(int32_t x, int32_t p, int32_t q);
  int plane_side(int32_t h, int32_t p);
  int plane_side_raw(int32_t h, int32_t p);
  int depth_x(int32_t g, int32_t h);
  size_t insert_at(int32_t f);
  size_t insert_at_crossing(int32_t f);
  size_t place(int32_t f, int32_t guess);
  int32_t track(int32_t f, int m, int32_t j);
  int depth_edges(int32_t g, int m);

  const QueryInput* in_ = nullptr;
  const ViewTables* view_ = nullptr;
  RayTerms terms_;                            // the current vertex's ray
  const PlaneKey& key(int32_t f);
  // Which of the current vertex's points face f holds (touch_bits), once per query.
  int touch(int32_t f);

  std::vector<int32_t> inside_, rays_, sector_, face_stamp_, key_stamp_;
  std::vector<int32_t> hits_;  // gather(): the bucket's faces whose boxes overlap the vertex's
  // emit_sectors' memos: per wedge the places of its rays in rays_; per pair of rays
  // their side, per pair of wedges before() (2: not asked yet).
  std::vector<int32_t> wedge_ray_;
  std::vector<int8_t> ray_side_, before_;
  std::vector<PlaneKey> key_;  // per face, valid where key_stamp_ is the current query
  std::vector<int32_t> touch_stamp_;  // per face: the query touch_ is valid for
  std::vector<uint8_t> touch_;        // per face: touch() bits
  int32_t vi_ = -1;            // the current query
  int32_t gather_ = 0;         // face_stamp_ of the current gather
  std::vector<std::pair<double, int32_t>> keys_;
  std::vector<Wedge> wedges_;
  const ArrVertex* current_ = nullptr;  // the vertex being queried
  VertexRay ray_;                        // and its ray
  // The vertex's projected position and radius for the double filter (uv_filter.h);
  // filter_ off in double / compare modes and when the view's uv rounding is too large.
  double xc_ = 0, yc_ = 0, rx_ = 0, ry_ = 0;
  // A bound on uv_side's own bound for every side test of the query (begin()): beyond it a
  // side is certain from orient2d's six operations alone (orient_raw). Infinite: none.
  double quick_ = INFINITY;
  bool filter_ = false, rechecked_ = false;
  bool undecided_ = false;  // a depth comparison returned 0 (the sweep then falls back)
  // The sweep's sorted covering faces of the open segment before the current crossing
  // (faces of the swept edge excluded), and the edge's crossings in order.
  std::vector<int32_t> list_;
  std::vector<EdgeCrossing> xings_;
  // Per point vertex, where ended_ holds its sorted strictly covering faces (a count, then
  // the faces) as the first sweep ending there left them, or -1 (keep_end_list).
  std::vector<int32_t> ended_at_, ended_;
  bool beside_ = false;         // the last crossing changed a neighbour of e's faces
  // The last sweep start: its point, covering faces sorted, and wedges.
  int32_t start_point_ = -1;
  std::vector<int32_t> start_inside_;
  std::vector<Wedge> start_wedges_;
  // The swept edge's faces, their positions in list_ (faces of list_ in front), the side
  // of the edge each covers (the sign of D), and their depth order where on one side.
  int32_t eface_[4] = {}, epos_[4] = {};
  int8_t eside_[4] = {};
  bool ebefore_[4][4] = {};
  int n_eface_ = 0;
  // The sweep's current crossing (vertex id, the crossing edge's points) and, per face
  // compared there, the side of its plane holding both points (0: none, or not certain).
  int32_t xvi_ = -1, xc_pt_ = -1, xd_pt_ = -1;
  int xsa_ = 0;        // point_side(a, c, d) at the current crossing, a the swept edge's first point
  int32_t swept_ = -1;  // the edge being swept
  // plane_side's memo (view-independent signs): key (h << 32 | p) + 1, 0 empty.
  static constexpr int kPlaneMemoBits = 12;
  std::vector<uint64_t> plane_memo_key_ = std::vector<uint64_t>(size_t{1} << kPlaneMemoBits, 0);
  std::vector<int8_t> plane_memo_sign_ = std::vector<int8_t>(size_t{1} << kPlaneMemoBits, 0);
  static constexpr int kPsign = 16;
  int n_psign_ = 0;
  int32_t psign_face_[kPsign] = {};
  int8_t psign_[kPsign] = {};
  // emit's table of recent pairs (key + 1; 0 empty); cleared when pairs are rolled back.
  static constexpr int kSeenBits = 12;
  std::vector<uint64_t> seen_ = std::vector<uint64_t>(size_t{1} << kSeenBits, 0);
};

// In this header: the sweeps (edge_sweep.cpp) and point queries call it millions of times
// a view.
inline void Worker::emit(int32_t nearer, int32_t farther) {
  // Leaving the mesh through `nearer`, entering it again through `farther`.
  const int32_t n = view_->facing_cell[nearer], f = view_->facing_cell[farther];
  if (n < 0 && f > 0 && -n != f) {
    const std::pair<int32_t, int32_t> p{-n - 1, f - 1};
    // Neighbouring vertices repeat pairs: a direct-mapped table of recent ones keeps most
    // repeats out of the final sort.
    const uint64_t key = (uint64_t(uint32_t(p.first)) << 32 | uint32_t(p.second)) + 1;
    uint64_t& slot = seen_[(key * 0x9E3779B97F4A7C15ull) >> (64 - kSeenBits)];
    if (slot == key) return;
    slot = key;
    pairs_.push_back(p);
  }
}

}  // namespace vob::xmpvo::detail
