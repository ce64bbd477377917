// XMPVO's full vertex query (Worker's part that finds and sorts the faces covering one
// arrangement vertex and emits its relations); the edge sweep is in edge_sweep.cpp, the
// views' driver in ray_queries.cpp.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "algorithms/xmpvo/plane_keys.h"
#include "algorithms/xmpvo/query_worker.h"
#include "algorithms/xmpvo/uv_filter.h"

namespace vob::xmpvo {
namespace detail {

// Sign of D(v, p, q): side of q relative to the projected line through v and p; with
// (p, q) an edge, the side of v relative to the edge.
int Worker::orient_at(const ArrVertex& v, int32_t p, int32_t q) {
  if (p == q) return 0;
  if (v.b < 0) {
    if (p == v.a || q == v.a) return 0;
  } else if ((p == v.a && q == v.b) || (p == v.b && q == v.a) || (p == v.c && q == v.d) ||
             (p == v.d && q == v.c)) {
    return 0;
  }
  return orient_raw(v, p, q);
}

// uv_side's o, against the query's bound first: beyond it the sign is the one uv_side
// would give (begin()), so only signs near the bound pay for uv_side's own.
int Worker::orient_raw(const ArrVertex& v, int32_t p, int32_t q) {
  if (filter_) {
    const Projection& pr = in_->proj;
    const Uv up = pr.uv[p], uq = pr.uv[q];
    const double ax = uq.first - up.first, ay = uq.second - up.second;
    const double o = ax * (yc_ - up.second) - ay * (xc_ - up.first);
    const int s = (o > quick_) - (o < -quick_);
    if (s != 0) {
      ++stats_.side_filtered;
      return pr.sign_n * s;
    }
  }
  return orient_filtered(v, p, q);
}

int Worker::orient_filtered(const ArrVertex& v, int32_t p, int32_t q) {
  if (filter_) {
    const Projection& pr = in_->proj;
    const int s = uv_side(xc_, yc_, rx_, ry_, pr.uv[p], pr.uv[q], pr.slack);
    if (s != 2) {
      ++stats_.side_filtered;
      return pr.sign_n * s;
    }
    ++stats_.side_rechecked;
    rechecked_ = true;
  }
  if (v.b < 0) return signs_.edge_side(pt(v.a), pt(p), pt(q));
  if (signs_.mode == Mode::Exact) {
    ++signs_.side;
    return vertex_side(ray_, pt(p), pt(q));
  }
  return signs_.crossing_side(pt(v.a), pt(v.b), pt(v.c), pt(v.d), pt(p), pt(q));
}

// Front-to-back depth order of two faces that both cover a region touching the query
// vertex: where the vertex's own ray meets their planes at different points that order
// holds over the whole overlap; otherwise (faces touching on that ray) the full test.
int Worker::depth(int32_t x, int32_t y) {
  ++stats_.depth_calls;
  const ExteriorFaces& e = in_->ext;
  // Faces sharing the vertex (or the crossing edge) meet the ray at the same point.
  int at = 0;
  if ((touch(x) & touch(y)) == 0) {
    at = compare_keys(key(x), key(y));
    if (at == 2) {
      ++stats_.depth_rechecked;
      rechecked_ = true;
      at = vertex_plane_order(ray_, in_->plane[x], in_->plane[y]);
    }
  }
  if (at != 0) return at;
  ++stats_.depth_full;
  const int r = depth_order(signs_.g, &e.corners[4 * x], e.size[x], &e.corners[4 * y], e.size[y]);
  stats_.depth_undecided += r == 0;
  undecided_ |= r == 0;
  return r;
}

const PlaneKey& Worker::key(int32_t f) {
  if (key_stamp_[f] != vi_) {
    key_stamp_[f] = vi_;
    key_[f] = plane_key(signs_.g, terms_, view_->view_plane[f]);
  }
  return key_[f];
}

uint8_t touch_bits(const ArrVertex& v, const int32_t* p, int n) {
  auto has = [&](int32_t q) { return p[0] == q || p[1] == q || p[2] == q || (n > 3 && p[3] == q); };
  return static_cast<uint8_t>(v.b < 0 ? has(v.a) : (has(v.a) && has(v.b)) | ((has(v.c) && has(v.d)) << 1));
}

int Worker::touch(int32_t f) {
  if (touch_stamp_[f] != vi_) {
    touch_stamp_[f] = vi_;
    touch_[f] = touch_bits(*current_, &in_->ext.vertex[4 * f], in_->ext.size[f]);
  }
  return touch_[f];
}

void Worker::run_query(int32_t vi) {
  begin(vi);
  const ArrVertex& v = *current_;
  gather(v);
  if (wedges_.empty()) return;
  const bool undecided = undecided_;
  undecided_ = false;
  sort_inside();
  const bool start = v.b < 0 && !undecided_;
  if (v.b < 0) start_point_ = -1;
  undecided_ |= undecided;
  if (start) emit_at_point(v);
  else emit_sectors(v);
}

// The sweeps from point v start from its sorted faces (start_list); then its relations.
void Worker::emit_at_point(const ArrVertex& v) {
  start_inside_ = inside_;
  start_wedges_ = wedges_;
  start_point_ = v.a;
  emit_sectors(v);
}

void Worker::query_and_sweep(int32_t vi, const int32_t* e0, const int32_t* e1) {
  if (!ended_at_.empty() && ended_at_[vi] >= 0) {
    run_query_after_sweep(vi);
  } else {
    query(vi);
  }
  if (degenerate_seen_) return;
  for (const int32_t* e = e0; e < e1; ++e) sweep_edge(*e);
  // Only a point query's degeneracy is the view's (a crossing's full query may meet one
  // in a sweep's fallback without making the other sweeps wrong).
  degenerate_seen_ = false;
}

void Worker::start_view(const QueryInput& in, const ViewTables& view) {
  // The state a newly made worker has, in the storage this one already holds.
  in_ = &in;
  view_ = &view;
  signs_ = in.signs;
  degenerate_seen_ = false;
  const size_t faces = in.ext.face.size();
  face_stamp_.assign(faces, -1);
  key_stamp_.assign(faces, -1);
  key_.resize(faces);
  touch_stamp_.assign(faces, -1);
  touch_.assign(faces, 0);
  ended_at_.assign(view.point_face_off.empty() ? 0 : view.point_face_off.size() - 1, -1);
  for (std::vector<int32_t>* v : {&inside_, &rays_, &sector_, &wedge_ray_, &list_, &start_inside_}) v->clear();
  ray_side_.clear(), before_.clear(), keys_.clear(), wedges_.clear(), xings_.clear(), start_wedges_.clear();
  vi_ = -1, gather_ = 0;
  current_ = nullptr;
  ray_ = VertexRay{}, terms_ = RayTerms{};
  xc_ = yc_ = rx_ = ry_ = 0;
  quick_ = INFINITY;
  filter_ = rechecked_ = undecided_ = beside_ = false;
  std::fill(std::begin(eface_), std::end(eface_), 0), std::fill(std::begin(epos_), std::end(epos_), 0);
  std::fill(std::begin(eside_), std::end(eside_), 0);
  for (auto& row : ebefore_) std::fill(std::begin(row), std::end(row), false);
  n_eface_ = 0;
  xvi_ = xc_pt_ = xd_pt_ = swept_ = -1;
  xsa_ = 0;
  std::fill(plane_memo_key_.begin(), plane_memo_key_.end(), 0);
  std::fill(plane_memo_sign_.begin(), plane_memo_sign_.end(), 0);
  n_psign_ = 0;
  std::fill(std::begin(psign_face_), std::end(psign_face_), 0), std::fill(std::begin(psign_), std::end(psign_), 0);
  reset();  // pairs, recent pairs, counters, the last start, the end lists
}

void Worker::reset() {
  pairs_.clear();
  std::fill(seen_.begin(), seen_.end(), 0);
  stats_ = QueryStats{};
  signs_.side = signs_.dis_side = 0;
  start_point_ = -1;
  std::fill(ended_at_.begin(), ended_at_.end(), -1);
  ended_.clear();
}

// The query context of vertex vi: its ray, depth terms and filter position.
void Worker::begin(int32_t vi) {
  const ArrVertex& v = in_->arr.vertices[vi];
  const Projection& proj = in_->proj;
  current_ = &v;
  vi_ = vi;
  ray_ = v.b < 0 ? VertexRay::at_point(signs_.g, pt(v.a))
                 : VertexRay::at_crossing(signs_.g, pt(v.a), pt(v.b), pt(v.c), pt(v.d));
  terms_ = RayTerms::of(ray_);
  ++stats_.vertex_queries;
  filter_ = signs_.mode == Mode::Exact && proj.uv_filter;
  if (v.b < 0) {
    std::tie(xc_, yc_) = proj.uv[v.a];
    rx_ = ry_ = proj.slack;
  } else {
    // The box holds the exact crossing; its centre's rounding widens it a little.
    xc_ = 0.5 * (v.box.x0 + v.box.x1), yc_ = 0.5 * (v.box.y0 + v.box.y1);
    rx_ = 0.5 * (v.box.x1 - v.box.x0) + 1e-15 * std::fabs(xc_) + 1e-300;
    ry_ = 0.5 * (v.box.y1 - v.box.y0) + 1e-15 * std::fabs(yc_) + 1e-300;
  }
  // Every side test of a query takes p and q among the vertices of faces whose boxes
  // overlap the vertex box (its own faces, those gather() classifies, the swept edge's),
  // so |q - p| and |x - p| are at most D = 2 widest + 4 r per coordinate. uv_sign's bound
  // is then at most D (ex + ey + 2 ea) + ea (ex + ey) + 2e-15 D^2, and its test 1.001 times
  // that, taken with 2% to spare for the rounding of both.
  quick_ = INFINITY;  // no sign beyond it
  if (filter_ && in_->quick_sides) {
    const double s = proj.slack, ea = 2 * s, ex = rx_ + s, ey = ry_ + s;
    const double d = 2 * view_->widest_face + 4 * std::max(rx_, ry_);
    quick_ = 1.02 * (d * (ex + ey + 2 * ea) + ea * (ex + ey) + 2e-15 * d * d);
    // NaN, or so small that the bound's terms may have underflowed: none.
    if (!(quick_ > 1e-290)) quick_ = INFINITY;
  }
}

// The faces whose closed projection holds v: inside_ (unsorted) and wedges_.
void Worker::gather(const ArrVertex& v) {
  const Projection& proj = in_->proj;
  inside_.clear();
  wedges_.clear();
  ++gather_;
  const BucketGrid& grid = proj.grid;
  const int c0 = grid.col(v.box.x0), c1 = grid.col(v.box.x1), r0 = grid.row(v.box.y0), r1 = grid.row(v.box.y1);
  // One bucket (most queries): it lists each face once, so no stamps.
  if (c0 == c1 && r0 == r1) {
    const size_t cell = static_cast<size_t>(r0) * grid.gw + c0;
    const int32_t x1 = proj.bucket_off[cell + 1];
    // The faces whose boxes overlap v's first, with no branch on the test (about two in
    // three pass, unpredictably), then classified.
    const int32_t* faces = proj.bucket_faces.data();
    const Box* box = proj.face_box.data();
    const Box q = v.box;
    hits_.resize(static_cast<size_t>(x1 - proj.bucket_off[cell]));
    size_t m = 0;
    for (int32_t x = proj.bucket_off[cell]; x < x1; ++x) {
      const int32_t f = faces[x];
      const Box& b = box[f];
      hits_[m] = f;
      m += (b.x0 <= q.x1) & (q.x0 <= b.x1) & (b.y0 <= q.y1) & (q.y0 <= b.y1);
    }
    for (size_t k = 0; k < m; ++k) classify(v, hits_[k]);
    return;
  }
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const size_t cell = static_cast<size_t>(r) * grid.gw + c;
      for (int32_t x = proj.bucket_off[cell]; x < proj.bucket_off[cell + 1]; ++x) {
        const int32_t f = proj.bucket_faces[x];
        if (face_stamp_[f] == gather_) continue;
        face_stamp_[f] = gather_;
        if (proj.face_box[f].overlaps(v.box)) classify(v, f);
      }
    }
}

// The relations at v from inside_ (sorted front to back) and wedges_.
void Worker::emit_sectors(const ArrVertex& v) {
  const int32_t ni = static_cast<int32_t>(inside_.size());
  // A face with the point v as a vertex meets v's ray at v, so each depth() against an
  // inside face (none holds v) is the sign of that face's depth against v's, the same for
  // all of them, unless a plane passes through v (0, then the full test, which may differ):
  // one search serves every such face when it met none.
  int32_t at_point = -1;
  for (Wedge& w : wedges_) {
    const bool own = v.b < 0 && (touch(w.face) & 1);
    if (own && at_point >= 0) {
      w.pos = at_point;
      continue;
    }
    const int64_t full = stats_.depth_full;
    int32_t lo = 0, hi = ni;
    while (lo < hi) {
      const int32_t mid = (lo + hi) / 2;
      if (depth(w.face, inside_[mid]) < 0) hi = mid;
      else lo = mid + 1;
    }
    w.pos = lo;
    if (own && stats_.depth_full == full) at_point = lo;
  }
  rays_.clear();
  wedge_ray_.clear();  // per wedge, the places of its s and t in rays_
  for (const Wedge& w : wedges_)
    for (int32_t r : {w.s, w.t}) {
      const auto at = std::find(rays_.begin(), rays_.end(), r);
      wedge_ray_.push_back(static_cast<int32_t>(at - rays_.begin()));
      if (at == rays_.end()) rays_.push_back(r);
    }
  // Every wedge is tested against every ray, and the wedges of a sector meet again in the
  // next ones: each side and each order is asked once a query. Exact signs are
  // antisymmetric, so one test gives both sides of a pair of rays.
  const size_t nr = rays_.size(), nw = wedges_.size();
  const bool exact = signs_.mode == Mode::Exact;
  ray_side_.assign(nr * nr, 2);
  before_.assign(nw * nw, 2);
  auto side = [&](int32_t i, int32_t j) {
    int8_t& m = ray_side_[i * nr + j];
    if (m == 2) {
      m = static_cast<int8_t>(orient_at(v, rays_[i], rays_[j]));
      if (exact) ray_side_[j * nr + i] = static_cast<int8_t>(-m);
    }
    return int(m);
  };
  // Whether wedge k covers the sector just counter-clockwise of ray r.
  auto covers = [&](size_t k, int32_t r) {
    const Wedge& w = wedges_[k];
    const int32_t si = wedge_ray_[2 * k], ti = wedge_ray_[2 * k + 1];
    if (r == si) return true;
    if (r == ti) return false;
    const int os = side(si, r);
    if (!w.half) return os >= 0 && side(r, ti) > 0;
    if (os != 0) return os > 0;
    return orient_at(v, rays_[r], w.ref) > 0;  // along s or opposite it
  };
  for (int32_t r = 0; r < static_cast<int32_t>(nr); ++r) {
    // The sector just counter-clockwise of ray r.
    sector_.clear();
    for (int32_t k = 0; k < static_cast<int32_t>(nw); ++k)
      if (covers(k, r)) sector_.push_back(k);
    ++stats_.sectors;
    stats_.sector_faces += ni + static_cast<int64_t>(sector_.size());
    // Insertion sort (terminates whatever the comparator says on invalid input).
    for (size_t j = 1; j < sector_.size(); ++j)
      for (size_t m = j; m > 0 && before(sector_[m], sector_[m - 1]); --m)
        std::swap(sector_[m], sector_[m - 1]);
    for (size_t j = 0; j < sector_.size(); ++j) {
      const Wedge& w = wedges_[sector_[j]];
      if (j > 0 && wedges_[sector_[j - 1]].pos == w.pos) emit(wedges_[sector_[j - 1]].face, w.face);
      else if (w.pos > 0) emit(inside_[w.pos - 1], w.face);
      const bool last_here = j + 1 == sector_.size() || wedges_[sector_[j + 1]].pos != w.pos;
      if (last_here && w.pos < ni) emit(w.face, inside_[w.pos]);
    }
    // The inside faces on either side of a boundary face that does not cover the sector
    // are consecutive there, unless a face covering it lies between them.
    for (const Wedge& w : wedges_) {
      if (w.pos == 0 || w.pos == ni) continue;
      bool between = false;
      for (int32_t k : sector_) between |= wedges_[k].pos == w.pos;
      if (!between) emit(inside_[w.pos - 1], inside_[w.pos]);
    }
  }
}

bool Worker::before(int32_t x, int32_t y) {
  const Wedge &a = wedges_[x], &b = wedges_[y];
  if (a.pos != b.pos) return a.pos < b.pos;
  int8_t& m = before_[x * wedges_.size() + y];
  if (m == 2) m = depth(a.face, b.face) < 0;
  return m;
}

void Worker::classify(const ArrVertex& v, int32_t f) {
  const int n = in_->ext.size[f];
  const int32_t* p = &in_->ext.vertex[4 * f];
  const int inner = -in_->proj.facing[f];  // edge_side of the projection's inside, every edge
  unsigned zeros = 0;
  for (int k = 0; k < n; ++k) {
    const int s = orient_at(v, p[k], p[k + 1 < n ? k + 1 : 0]) * inner;
    if (s < 0) return;
    if (s == 0) zeros |= 1u << k;
  }
  // depth()'s touch bits, while the face's points are at hand.
  touch_stamp_[f] = vi_;
  touch_[f] = touch_bits(v, p, n);
  if (zeros == 0) {
    inside_.push_back(f);
    // Its plane key is computed next (sort_inside): asked for now.
    __builtin_prefetch(&view_->view_plane[f]);
    return;
  }
  // Its key is needed when it meets an inside face in a sector (emit_sectors).
  __builtin_prefetch(&view_->view_plane[f]);
  // A point on the boundary of a face it is not a vertex of: the edge sweep's premise fails.
  if (v.b < 0 && p[0] != v.a && p[1] != v.a && p[2] != v.a && (n < 4 || p[3] != v.a))
    degenerate_seen_ = true;
  const int count = __builtin_popcount(zeros);
  const int k = __builtin_ctz(zeros);
  Wedge w{f, 0, 0, 0, count == 1, 0};
  if (count == 1) {
    const int32_t a = p[k], b = p[(k + 1) % n];
    w.s = inner > 0 ? b : a;
    w.t = inner > 0 ? a : b;
    w.ref = p[(k + 2) % n];
  } else if (count == 2) {
    // Zero sides on edges j-1 and j: v is on the ray of vertex j.
    int j = 0;
    while (j < n && zeros != ((1u << j) | (1u << ((j + n - 1) % n)))) ++j;
    if (j == n) { ++stats_.degenerate; degenerate_seen_ = true; return; }
    const int32_t a = p[(j + n - 1) % n], b = p[(j + 1) % n];
    w.s = inner > 0 ? b : a;
    w.t = inner > 0 ? a : b;
  } else {
    ++stats_.degenerate;
    degenerate_seen_ = true;
    return;
  }
  wedges_.push_back(w);
}

// Inside faces front to back: by the plane keys' approximate ray parameters (the keys are
// needed for the exact comparisons anyway), then an insertion pass with the exact order
// (linear when the approximation is right).
void Worker::sort_inside() {
  keys_.clear();
  for (int32_t f : inside_) {
    const PlaneKey& k = key(f);
    double t = k.num.v / k.den.v;
    if (!(t == t)) t = 0;
    keys_.push_back({t, f});
  }
  std::sort(keys_.begin(), keys_.end());
  for (size_t j = 0; j < keys_.size(); ++j) inside_[j] = keys_[j].second;
  for (size_t j = 1; j < inside_.size(); ++j)
    for (size_t m = j; m > 0 && depth(inside_[m], inside_[m - 1]) < 0; --m)
      std::swap(inside_[m], inside_[m - 1]);
}

}  // namespace detail

}  // namespace vob::xmpvo
