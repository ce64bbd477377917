#include "algorithms/xmpvo/xmpvo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/xmpvo/face_pairs.h"

namespace vob {
namespace {

using xmpvo::ViewGeometry;

enum class Mode { Exact, Double, Compare };

// Faces whose nearest vertex is within this fraction of (scene radius + eye distance) of
// a perspective eye's plane are not projected: the projection would blow up.
constexpr double kFrontRelative = 1e-9;
// Bucketing slack, relative to the projected extent: far above the rounding of projected
// doubles (~1e-15), so a face whose exact projection holds a point is always found.
constexpr double kSlackRelative = 1e-9;

// Every sign decision of the per-view work, in the chosen arithmetic; compare mode
// evaluates both and counts where they differ.
struct Signs {
  Mode mode = Mode::Exact;
  ViewGeometry g;
  int64_t facing = 0, side = 0, crossing = 0;                    // decisions
  int64_t dis_facing = 0, dis_side = 0, dis_crossing = 0;         // disagreements

  int eye_side(Vec3 a, Vec3 b, Vec3 c) {
    ++facing;
    if (mode == Mode::Double) return xmpvo::eye_side_double(g, a, b, c);
    const int e = xmpvo::eye_side(g, a, b, c);
    if (mode == Mode::Compare) dis_facing += e != xmpvo::eye_side_double(g, a, b, c);
    return e;
  }
  int edge_side(Vec3 a, Vec3 b, Vec3 p) {
    ++side;
    if (mode == Mode::Double) return xmpvo::edge_side_double(g, a, b, p);
    const int e = xmpvo::edge_side(g, a, b, p);
    if (mode == Mode::Compare) dis_side += e != xmpvo::edge_side_double(g, a, b, p);
    return e;
  }
  int crossing_side(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q) {
    ++side;
    if (mode == Mode::Double) return xmpvo::crossing_side_double(g, a, b, c, d, p, q);
    const int e = xmpvo::crossing_side(g, a, b, c, d, p, q);
    if (mode == Mode::Compare) dis_side += e != xmpvo::crossing_side_double(g, a, b, c, d, p, q);
    return e;
  }
  // Proper crossing of projected segments (a, b) and (c, d).
  bool crosses(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    ++crossing;
    auto test = [&](auto side) {
      return side(c, d, a) * side(c, d, b) < 0 && side(a, b, c) * side(a, b, d) < 0;
    };
    auto exact = [&](Vec3 x, Vec3 y, Vec3 z) { return xmpvo::edge_side(g, x, y, z); };
    auto plain = [&](Vec3 x, Vec3 y, Vec3 z) { return xmpvo::edge_side_double(g, x, y, z); };
    if (mode == Mode::Double) return test(plain);
    const bool e = test(exact);
    if (mode == Mode::Compare) dis_crossing += e != test(plain);
    return e;
  }
};

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

// An arrangement vertex: a projected boundary point (b < 0), or the proper crossing of the
// projected edges (a, b) and (c, d). Ids are compact boundary point ids.
struct ArrVertex {
  int32_t a, b, c, d;
  double t;  // crossing: approximate parameter along (a, b), for depth keys only
  Box box;   // where its exact position lies, in projected doubles
};

// A face with the query vertex on its projected boundary: it covers the directions from
// ray s counter-clockwise (in the sign convention of D) to ray t; a half-plane when the
// vertex is inside an edge, then `ref` is a face vertex strictly inside it.
struct Wedge {
  int32_t face, s, t, ref;
  bool half;
  int32_t pos;  // number of inside faces in front of it
};

struct Stats {
  int64_t vertex_queries = 0, sectors = 0, sector_faces = 0, depth_calls = 0,
          depth_full = 0, depth_undecided = 0, degenerate = 0;
};

class XmpvoOrderer final : public Orderer {
 public:
  explicit XmpvoOrderer(Mode mode) : mode_(mode) {}
  Claims claims() const override {
    Claims c;
    c.object_exact = true;
    c.detects_cycles = true;
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    { auto p = clock.phase("unique faces"); scene.faces(); }
    { auto p = clock.phase("face planes"); scene.face_planes(); }
    core_.bind(scene);
    core_.set_plain_double_signs(mode_ == Mode::Double);
    auto p = clock.phase("exterior face list");
    const MeshFaces& faces = core_.faces();
    const CellMesh& mesh = core_.scene().mesh();
    const size_t b = faces.boundary.size();
    ext_face_ = faces.boundary;
    ext_n_.resize(b);
    ext_cell_.resize(b);
    ext_pt_.assign(4 * b, -1);
    std::vector<int32_t> compact(mesh.points.size(), -1);
    points_.clear();
    for (size_t i = 0; i < b; ++i) {
      const int32_t f = ext_face_[i];
      const int n = faces.face_size(f);
      for (int k = 0; k < n; ++k) {
        const int32_t pid = faces.face_points(f)[k];
        if (compact[pid] < 0) {
          compact[pid] = static_cast<int32_t>(points_.size());
          points_.push_back(mesh.points[pid]);
        }
        ext_pt_[4 * i + k] = compact[pid];
      }
      ext_n_[i] = static_cast<int8_t>(n);
      ext_cell_[i] = faces.cell0[f];
    }
    plane_.resize(b);
    for (size_t i = 0; i < b; ++i) {
      const Vec3 f3[3] = {points_[ext_pt_[4 * i]], points_[ext_pt_[4 * i + 1]], points_[ext_pt_[4 * i + 2]]};
      plane_[i] = xmpvo::FacePlane::of(f3);
    }
    const Aabb box = mesh.bounds();
    centre_ = box.center();
    radius_ = box.radius();
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    signs_ = Signs{};
    signs_.mode = mode_;
    signs_.g = ViewGeometry::of(view);
    stats_ = Stats{};
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
    }
    {
      auto p = clock.phase("project");
      project(view);
    }
    int64_t candidates = 0;
    {
      auto p = clock.phase("arrangement vertices");
      candidates = arrangement_vertices();
    }
    {
      auto p = clock.phase("ray queries");
      // Queries are independent: threads take runs of vertices; the relation set, sorted
      // and deduplicated, and the summed counters do not depend on the split.
      tbb::enumerable_thread_specific<Worker> workers([this] { return Worker(*this); });
      tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices_.size(), 512),
                        [&](const tbb::blocked_range<size_t>& r) {
                          Worker& w = workers.local();
                          for (size_t v = r.begin(); v < r.end(); ++v) w.query(static_cast<int32_t>(v));
                        });
      pairs_.clear();
      worker_bytes_ = 0;
      for (Worker& w : workers) {
        pairs_.insert(pairs_.end(), w.pairs_.begin(), w.pairs_.end());
        worker_bytes_ += w.bytes();
        Stats& t = stats_;
        const Stats& x = w.stats_;
        t.vertex_queries += x.vertex_queries, t.sectors += x.sectors, t.sector_faces += x.sector_faces;
        t.depth_calls += x.depth_calls, t.depth_full += x.depth_full;
        t.depth_undecided += x.depth_undecided, t.degenerate += x.degenerate;
        signs_.side += w.signs_.side, signs_.dis_side += w.signs_.dis_side;
      }
      std::sort(pairs_.begin(), pairs_.end());
      pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
      extra_.build_from_pairs(core_.num_cells(), pairs_);
    }
    {
      auto p = clock.phase("DFS");
      core_.dfs_all(out, &extra_);
    }
    core_.add_counters(out);
    auto& k = out.counters;
    k["exterior_faces"] = static_cast<double>(ext_face_.size());
    k["front_facing"] = static_cast<double>(front_);
    k["back_facing"] = static_cast<double>(back_);
    k["edge_on_faces"] = static_cast<double>(edge_on_);
    k["faces_behind_eye"] = static_cast<double>(behind_eye_);
    k["faces_crossing_eye_plane"] = static_cast<double>(crossing_eye_);
    k["skipped_faces"] = static_cast<double>(crossing_eye_);
    k["projected_vertices"] = static_cast<double>(projected_vertices_);
    k["edge_crossings"] = static_cast<double>(vertices_.size() - projected_vertices_);
    k["candidate_edge_pairs"] = static_cast<double>(candidates);
    k["vertex_queries"] = static_cast<double>(stats_.vertex_queries);
    k["ray_queries"] = static_cast<double>(stats_.sectors);
    k["faces_per_query"] =
        stats_.sectors ? static_cast<double>(stats_.sector_faces) / stats_.sectors : 0.0;
    k["depth_order_calls"] = static_cast<double>(stats_.depth_calls);
    k["depth_order_full"] = static_cast<double>(stats_.depth_full);
    k["depth_undecided"] = static_cast<double>(stats_.depth_undecided);
    k["degenerate_coverage"] = static_cast<double>(stats_.degenerate);
    k["relations"] = static_cast<double>(pairs_.size());
    k["grid_buckets"] = static_cast<double>(gw_) * gh_;
    if (mode_ == Mode::Compare) {
      k["facing_decisions"] = static_cast<double>(signs_.facing);
      k["side_decisions"] = static_cast<double>(signs_.side);
      k["crossing_decisions"] = static_cast<double>(signs_.crossing);
      k["disagree_facing"] = static_cast<double>(signs_.dis_facing);
      k["disagree_side"] = static_cast<double>(signs_.dis_side);
      k["disagree_crossing"] = static_cast<double>(signs_.dis_crossing);
      k["disagree_arrows"] = static_cast<double>(core_.double_sign_wrong());
    }
    k["bytes_mpvo"] = static_cast<double>(core_.bytes());
    k["bytes_faces"] =
        static_cast<double>(core_.faces().bytes() + core_.scene().face_planes().bytes());
    k["bytes_exterior"] = static_cast<double>(exterior_bytes());
    k["bytes_arrangement"] = static_cast<double>(arrangement_bytes());
    k["bytes_relations"] = static_cast<double>(extra_.bytes() + pairs_.capacity() * 8);
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + exterior_bytes() + arrangement_bytes() + extra_.bytes() +
           pairs_.capacity() * 8;
  }

 private:
  size_t exterior_bytes() const {
    return ext_face_.capacity() * 4 + ext_n_.capacity() + ext_cell_.capacity() * 4 +
           ext_pt_.capacity() * 4 + points_.capacity() * sizeof(Vec3) + facing_.capacity() +
           plane_.capacity() * sizeof(xmpvo::FacePlane) +
           face_box_.capacity() * sizeof(Box) + uv_.capacity() * 16 + point_used_.capacity();
  }
  size_t arrangement_bytes() const {
    return bucket_off_.capacity() * 4 + bucket_faces_.capacity() * 4 + edges_.capacity() * 8 +
           edge_off_.capacity() * 4 + edge_items_.capacity() * 4 +
           vertices_.capacity() * sizeof(ArrVertex) + worker_bytes_;
  }

  // ---- project ----
  void project(const Camera& view) {
    const size_t b = ext_face_.size();
    const Vec3 eye = view.eye, fw = view.forward(), rt = view.right(), up = view.true_up();
    const double front_min = kFrontRelative * (radius_ + length(eye - centre_));
    facing_.assign(b, 0);
    uv_.resize(points_.size());
    point_used_.assign(points_.size(), 0);
    front_ = back_ = edge_on_ = behind_eye_ = crossing_eye_ = 0;
    // Depth along the view direction decides which perspective faces can be projected.
    for (size_t i = 0; i < b; ++i) {
      const int n = ext_n_[i];
      const int32_t* pt = &ext_pt_[4 * i];
      if (!view.ortho) {
        int in_front = 0;
        for (int k = 0; k < n; ++k) in_front += dot(points_[pt[k]] - eye, fw) > front_min;
        if (in_front == 0) { ++behind_eye_; continue; }
        if (in_front < n) { ++crossing_eye_; continue; }
      }
      const int s = signs_.eye_side(points_[pt[0]], points_[pt[1]], points_[pt[2]]);
      if (s == 0) { ++edge_on_; continue; }
      facing_[i] = static_cast<int8_t>(s);
      (s > 0 ? front_ : back_)++;
      for (int k = 0; k < n; ++k) point_used_[pt[k]] = 1;
    }
    // Projected doubles, for bucketing and depth keys only.
    Box all{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p < points_.size(); ++p) {
      if (!point_used_[p]) continue;
      const Vec3 d = points_[p] - eye;
      double u = dot(d, rt), v = dot(d, up);
      if (!view.ortho) {
        const double z = dot(d, fw);
        u /= z;
        v /= z;
      }
      uv_[p] = {u, v};
      all = {std::min(all.x0, u), std::min(all.y0, v), std::max(all.x1, u), std::max(all.y1, v)};
    }
    kept_.clear();
    for (size_t i = 0; i < b; ++i)
      if (facing_[i]) kept_.push_back(static_cast<int32_t>(i));
    if (kept_.empty()) all = {0, 0, 1, 1};
    const double w = std::max(all.x1 - all.x0, 0.0), h = std::max(all.y1 - all.y0, 0.0);
    slack_ = kSlackRelative * (std::max({std::fabs(all.x0), std::fabs(all.x1), std::fabs(all.y0),
                                         std::fabs(all.y1)}) + std::max(w, h)) + 1e-300;
    // About one face per bucket, square buckets where the extent allows.
    const double target = std::max<double>(1.0, static_cast<double>(kept_.size()));
    const double ww = std::max(w, 1e-12 * (w + h) + 1e-300), hh = std::max(h, 1e-12 * (w + h) + 1e-300);
    gw_ = static_cast<int>(std::clamp(std::sqrt(target * ww / hh), 1.0, 16384.0));
    gh_ = static_cast<int>(std::clamp(target / gw_, 1.0, 16384.0));
    gx0_ = all.x0 - slack_;
    gy0_ = all.y0 - slack_;
    cw_ = (w + 2 * slack_) / gw_;
    ch_ = (h + 2 * slack_) / gh_;
    face_box_.resize(b);
    for (int32_t i : kept_) {
      Box bx{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (int k = 0; k < ext_n_[i]; ++k) {
        const auto [u, v] = uv_[ext_pt_[4 * i + k]];
        bx = {std::min(bx.x0, u), std::min(bx.y0, v), std::max(bx.x1, u), std::max(bx.y1, v)};
      }
      face_box_[i] = {bx.x0 - slack_, bx.y0 - slack_, bx.x1 + slack_, bx.y1 + slack_};
    }
    fill_buckets(kept_, [&](int32_t i) { return face_box_[i]; }, bucket_off_, bucket_faces_);
  }

  int col(double x) const {
    return static_cast<int>(std::clamp(std::floor((x - gx0_) / cw_), 0.0, gw_ - 1.0));
  }
  int row(double y) const {
    return static_cast<int>(std::clamp(std::floor((y - gy0_) / ch_), 0.0, gh_ - 1.0));
  }

  // CSR of items per bucket from their boxes.
  template <class BoxOf>
  void fill_buckets(const std::vector<int32_t>& items, BoxOf box_of, std::vector<int32_t>& off,
                    std::vector<int32_t>& out) {
    off.assign(static_cast<size_t>(gw_) * gh_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      for (int32_t it : items) {
        const Box bx = box_of(it);
        const int c0 = col(bx.x0), c1 = col(bx.x1), r0 = row(bx.y0), r1 = row(bx.y1);
        for (int r = r0; r <= r1; ++r)
          for (int c = c0; c <= c1; ++c) {
            const size_t cell = static_cast<size_t>(r) * gw_ + c;
            if (pass == 0) ++off[cell + 1];
            else out[off[cell]++] = it;
          }
      }
      if (pass == 0) {
        for (size_t c = 1; c < off.size(); ++c) off[c] += off[c - 1];
        out.resize(off.back());
      } else {
        // The fill advanced each start to the next bucket's start: shift back.
        for (size_t c = off.size() - 1; c > 0; --c) off[c] = off[c - 1];
        off[0] = 0;
      }
    }
  }

  // ---- arrangement vertices ----
  Box point_box(int32_t p) const {
    const auto [u, v] = uv_[p];
    return {u - slack_, v - slack_, u + slack_, v + slack_};
  }
  Box edge_box(int32_t e) const {
    const Box a = point_box(edges_[e].first), b = point_box(edges_[e].second);
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
  }

  int64_t arrangement_vertices() {
    vertices_.clear();
    for (size_t p = 0; p < points_.size(); ++p)
      if (point_used_[p]) vertices_.push_back({static_cast<int32_t>(p), -1, -1, -1, 0, point_box(p)});
    projected_vertices_ = vertices_.size();
    // Unique projected edges (an edge shared by two exterior faces is one segment).
    std::vector<uint64_t> keys;
    keys.reserve(4 * kept_.size());
    for (int32_t i : kept_) {
      const int n = ext_n_[i];
      for (int k = 0; k < n; ++k) {
        uint32_t a = ext_pt_[4 * i + k], b = ext_pt_[4 * i + (k + 1) % n];
        if (a > b) std::swap(a, b);
        keys.push_back((uint64_t(a) << 32) | b);
      }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    edges_.resize(keys.size());
    std::vector<int32_t> ids(keys.size());
    for (size_t e = 0; e < keys.size(); ++e) {
      edges_[e] = {static_cast<int32_t>(keys[e] >> 32), static_cast<int32_t>(keys[e] & 0xffffffffu)};
      ids[e] = static_cast<int32_t>(e);
    }
    fill_buckets(ids, [&](int32_t e) { return edge_box(e); }, edge_off_, edge_items_);
    int64_t candidates = 0;
    for (int r = 0; r < gh_; ++r)
      for (int c = 0; c < gw_; ++c) {
        const size_t cell = static_cast<size_t>(r) * gw_ + c;
        for (int32_t x = edge_off_[cell]; x < edge_off_[cell + 1]; ++x)
          for (int32_t y = x + 1; y < edge_off_[cell + 1]; ++y) {
            const auto [a, b] = edges_[edge_items_[x]];
            const auto [cc, d] = edges_[edge_items_[y]];
            if (a == cc || a == d || b == cc || b == d) continue;  // no proper crossing
            const Box ba = edge_box(edge_items_[x]), bb = edge_box(edge_items_[y]);
            if (!ba.overlaps(bb)) continue;
            // Test each pair once: in the bucket of its boxes' common lower corner.
            if (col(std::max(ba.x0, bb.x0)) != c || row(std::max(ba.y0, bb.y0)) != r) continue;
            ++candidates;
            if (!signs_.crosses(points_[a], points_[b], points_[cc], points_[d])) continue;
            vertices_.push_back(crossing_vertex(a, b, cc, d, ba, bb));
          }
      }
    return candidates;
  }

  // Where the crossing of (a, b) and (c, d) lies in projected doubles: the computed point
  // with a generous error radius, inside both edges' boxes; their whole common box when
  // the doubles are too close to call.
  ArrVertex crossing_vertex(int32_t a, int32_t b, int32_t c, int32_t d, const Box& ba, const Box& bb) const {
    const Box common{std::max(ba.x0, bb.x0), std::max(ba.y0, bb.y0), std::min(ba.x1, bb.x1),
                     std::min(ba.y1, bb.y1)};
    ArrVertex v{a, b, c, d, 0.5, common};
    const auto [ax, ay] = uv_[a];
    const auto [bx, by] = uv_[b];
    const auto [cx, cy] = uv_[c];
    const auto [dx, dy] = uv_[d];
    auto orient = [](double ox, double oy, double px, double py, double qx, double qy) {
      return (px - ox) * (qy - oy) - (py - oy) * (qx - ox);
    };
    const double oa = orient(cx, cy, dx, dy, ax, ay), ob = orient(cx, cy, dx, dy, bx, by);
    if (!(oa * ob < 0)) return v;
    const double t = oa / (oa - ob);
    const double mag = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by),
                                 std::fabs(cx), std::fabs(cy), std::fabs(dx), std::fabs(dy)});
    const double lcd = std::hypot(dx - cx, dy - cy), lab = std::hypot(bx - ax, by - ay);
    const double err = 1e-12 * mag * (lcd + 2 * lab + 2 * mag) / std::fabs(oa - ob) * lab + slack_;
    const double x = ax + t * (bx - ax), y = ay + t * (by - ay);
    v.t = t;
    v.box = {std::max(common.x0, x - err), std::max(common.y0, y - err),
             std::min(common.x1, x + err), std::min(common.y1, y + err)};
    if (!(v.box.x0 <= v.box.x1 && v.box.y0 <= v.box.y1)) v.box = common;
    return v;
  }

  // ---- ray queries ----
  // One thread's share of the queries: its own scratch, counters and relation pairs; the
  // orderer's per-view data is read only.
  struct Worker {
    XmpvoOrderer& o;
    Signs signs_;
    Stats stats_;
    std::vector<int32_t> inside_, rays_, sector_, face_stamp_;
    std::vector<std::pair<double, int32_t>> keys_;
    std::vector<Wedge> wedges_;
    std::vector<std::pair<int32_t, int32_t>> pairs_;
    const ArrVertex* current_ = nullptr;  // the vertex being queried
    xmpvo::VertexRay ray_;                 // and its ray

    explicit Worker(XmpvoOrderer& owner) : o(owner), face_stamp_(owner.ext_face_.size(), -1) {
      signs_.mode = owner.signs_.mode;
      signs_.g = owner.signs_.g;
    }
    size_t bytes() const {
      return (inside_.capacity() + rays_.capacity() + sector_.capacity() + face_stamp_.capacity()) * 4 +
             keys_.capacity() * 16 + wedges_.capacity() * sizeof(Wedge) + pairs_.capacity() * 8;
    }
    // Sign of D(v, p, q): side of q relative to the projected line through v and p; with
    // (p, q) an edge, the side of v relative to the edge.
    int orient_at(const ArrVertex& v, int32_t p, int32_t q) {
      if (p == q) return 0;
      if (v.b < 0) {
        if (p == v.a || q == v.a) return 0;
        return signs_.edge_side(o.points_[v.a], o.points_[p], o.points_[q]);
      }
      if ((p == v.a && q == v.b) || (p == v.b && q == v.a) || (p == v.c && q == v.d) ||
          (p == v.d && q == v.c))
        return 0;
      if (o.mode_ == Mode::Exact) {
        ++signs_.side;
        return xmpvo::vertex_side(ray_, o.points_[p], o.points_[q]);
      }
      return signs_.crossing_side(o.points_[v.a], o.points_[v.b], o.points_[v.c], o.points_[v.d],
                                  o.points_[p], o.points_[q]);
    }

    // Front-to-back depth order of two faces that both cover a region touching the query
    // vertex: where the vertex's own ray meets their planes at different points that order
    // holds over the whole overlap; otherwise (faces touching on that ray) the full test.
    int depth(int32_t x, int32_t y) {
      ++stats_.depth_calls;
      Vec3 a[4], b[4];
      for (int k = 0; k < o.ext_n_[x]; ++k) a[k] = o.points_[o.ext_pt_[4 * x + k]];
      for (int k = 0; k < o.ext_n_[y]; ++k) b[k] = o.points_[o.ext_pt_[4 * y + k]];
      const ArrVertex& v = *current_;
      auto has = [&](int32_t f, int32_t p) {
        for (int k = 0; k < o.ext_n_[f]; ++k)
          if (o.ext_pt_[4 * f + k] == p) return true;
        return false;
      };
      // Faces sharing the vertex (or the crossing edge) meet the ray at the same point.
      const bool touch = v.b < 0 ? has(x, v.a) && has(y, v.a)
                                 : (has(x, v.a) && has(x, v.b) && has(y, v.a) && has(y, v.b)) ||
                                       (has(x, v.c) && has(x, v.d) && has(y, v.c) && has(y, v.d));
      const int at = touch ? 0 : xmpvo::vertex_plane_order(ray_, o.plane_[x], o.plane_[y]);
      if (at != 0) return at;
      ++stats_.depth_full;
      const int r = xmpvo::depth_order(signs_.g, a, o.ext_n_[x], b, o.ext_n_[y]);
      stats_.depth_undecided += r == 0;
      return r;
    }

    void emit(int32_t nearer, int32_t farther) {
      // Leaving the mesh through `nearer`, entering it again through `farther`.
      if (o.facing_[nearer] < 0 && o.facing_[farther] > 0 && o.ext_cell_[nearer] != o.ext_cell_[farther])
        pairs_.push_back({o.ext_cell_[nearer], o.ext_cell_[farther]});
    }

    bool covers_after(const ArrVertex& v, const Wedge& w, int32_t ray) {
      if (ray == w.s) return true;
      if (ray == w.t) return false;
      const int os = orient_at(v, w.s, ray);
      if (!w.half) return os >= 0 && orient_at(v, ray, w.t) > 0;
      if (os != 0) return os > 0;
      return orient_at(v, ray, w.ref) > 0;  // along s or opposite it
    }

    void query(int32_t vi) {
      const ArrVertex& v = o.vertices_[vi];
      current_ = &v;
      ray_ = v.b < 0 ? xmpvo::VertexRay::at_point(signs_.g, o.points_[v.a])
                     : xmpvo::VertexRay::at_crossing(signs_.g, o.points_[v.a], o.points_[v.b],
                                                     o.points_[v.c], o.points_[v.d]);
      ++stats_.vertex_queries;
      inside_.clear();
      wedges_.clear();
      const int c0 = o.col(v.box.x0), c1 = o.col(v.box.x1), r0 = o.row(v.box.y0), r1 = o.row(v.box.y1);
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
          const size_t cell = static_cast<size_t>(r) * o.gw_ + c;
          for (int32_t x = o.bucket_off_[cell]; x < o.bucket_off_[cell + 1]; ++x) {
            const int32_t f = o.bucket_faces_[x];
            if (face_stamp_[f] == vi) continue;
            face_stamp_[f] = vi;
            if (o.face_box_[f].overlaps(v.box)) classify(v, f);
          }
        }
      if (wedges_.empty()) return;
      sort_inside(v);
      const int32_t ni = static_cast<int32_t>(inside_.size());
      for (Wedge& w : wedges_) {
        int32_t lo = 0, hi = ni;
        while (lo < hi) {
          const int32_t mid = (lo + hi) / 2;
          if (depth(w.face, inside_[mid]) < 0) hi = mid;
          else lo = mid + 1;
        }
        w.pos = lo;
        // The inside faces on either side of a boundary face are consecutive where it is not.
        if (lo > 0 && lo < ni) emit(inside_[lo - 1], inside_[lo]);
      }
      rays_.clear();
      for (const Wedge& w : wedges_)
        for (int32_t r : {w.s, w.t})
          if (std::find(rays_.begin(), rays_.end(), r) == rays_.end()) rays_.push_back(r);
      for (int32_t ray : rays_) {
        // The sector just counter-clockwise of `ray`.
        sector_.clear();
        for (int32_t k = 0; k < static_cast<int32_t>(wedges_.size()); ++k)
          if (covers_after(v, wedges_[k], ray)) sector_.push_back(k);
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
      }
    }

    bool before(int32_t x, int32_t y) {
      const Wedge &a = wedges_[x], &b = wedges_[y];
      if (a.pos != b.pos) return a.pos < b.pos;
      return depth(a.face, b.face) < 0;
    }

    void classify(const ArrVertex& v, int32_t f) {
      const int n = o.ext_n_[f];
      const int32_t* pt = &o.ext_pt_[4 * f];
      const int inner = -o.facing_[f];  // edge_side of the projection's inside, every edge
      unsigned zeros = 0;
      for (int k = 0; k < n; ++k) {
        const int s = orient_at(v, pt[k], pt[(k + 1) % n]) * inner;
        if (s < 0) return;
        if (s == 0) zeros |= 1u << k;
      }
      if (zeros == 0) {
        inside_.push_back(f);
        return;
      }
      const int count = __builtin_popcount(zeros);
      const int k = __builtin_ctz(zeros);
      Wedge w{f, 0, 0, 0, count == 1, 0};
      if (count == 1) {
        const int32_t p = pt[k], q = pt[(k + 1) % n];
        w.s = inner > 0 ? q : p;
        w.t = inner > 0 ? p : q;
        w.ref = pt[(k + 2) % n];
      } else if (count == 2) {
        // Zero sides on edges j-1 and j: v is on the ray of vertex j.
        int j = 0;
        while (j < n && zeros != ((1u << j) | (1u << ((j + n - 1) % n)))) ++j;
        if (j == n) { ++stats_.degenerate; return; }
        const int32_t p = pt[(j + n - 1) % n], q = pt[(j + 1) % n];
        w.s = inner > 0 ? q : p;
        w.t = inner > 0 ? p : q;
      } else {
        ++stats_.degenerate;
        return;
      }
      wedges_.push_back(w);
    }

    // Inside faces front to back: approximate depth along v's ray, then an insertion pass
    // with the exact order (linear when the keys are right).
    void sort_inside(const ArrVertex& v) {
      const Vec3 eye = signs_.g.eye;
      Vec3 at = o.points_[v.a];
      if (v.b >= 0) at = o.points_[v.a] + (o.points_[v.b] - o.points_[v.a]) * v.t;
      const Vec3 org = signs_.g.ortho ? at : eye;
      const Vec3 d = signs_.g.ortho ? signs_.g.dir : at - eye;
      const FacePlanes& planes = o.core_.scene().face_planes();
      keys_.clear();
      for (int32_t f : inside_) {
        const Vec3 n = planes.normal[o.ext_face_[f]];
        double t = -(dot(n, org) + planes.offset[o.ext_face_[f]]) / dot(n, d);
        if (!(t == t)) t = 0;
        keys_.push_back({t, f});
      }
      std::sort(keys_.begin(), keys_.end());
      for (size_t j = 0; j < keys_.size(); ++j) inside_[j] = keys_[j].second;
      for (size_t j = 1; j < inside_.size(); ++j)
        for (size_t m = j; m > 0 && depth(inside_[m], inside_[m - 1]) < 0; --m)
          std::swap(inside_[m], inside_[m - 1]);
    }

  };

  Mode mode_;
  mpvo::MpvoCore core_;
  // Exterior face list (prepare): face id, size, owner, compact point ids, points.
  std::vector<int32_t> ext_face_;
  std::vector<int8_t> ext_n_;
  std::vector<int32_t> ext_cell_;
  std::vector<int32_t> ext_pt_;
  std::vector<Vec3> points_;
  std::vector<xmpvo::FacePlane> plane_;  // exact-filter planes of the exterior faces
  Vec3 centre_{};
  double radius_ = 0;
  // Per view.
  Signs signs_;
  Stats stats_;
  std::vector<int8_t> facing_;  // +1 front, -1 back, 0 not projected
  std::vector<int32_t> kept_;
  std::vector<uint8_t> point_used_;
  std::vector<std::pair<double, double>> uv_;
  std::vector<Box> face_box_;
  std::vector<int32_t> face_stamp_;
  int64_t front_ = 0, back_ = 0, edge_on_ = 0, behind_eye_ = 0, crossing_eye_ = 0;
  size_t projected_vertices_ = 0;
  int gw_ = 1, gh_ = 1;
  double gx0_ = 0, gy0_ = 0, cw_ = 1, ch_ = 1, slack_ = 0;
  std::vector<int32_t> bucket_off_, bucket_faces_;
  std::vector<std::pair<int32_t, int32_t>> edges_;
  std::vector<int32_t> edge_off_, edge_items_;
  std::vector<ArrVertex> vertices_;
  size_t worker_bytes_ = 0;  // the query threads' scratch at the last view
  std::vector<std::pair<int32_t, int32_t>> pairs_;
  mpvo::ExtraRelations extra_;
};

}  // namespace

OrdererInfo xmpvo_orderer_info() {
  return {"xmpvo", SceneKind::Cells,
          "Silva et al.'s XMPVO: MPVO arrows plus exterior-cell relations from exact ray "
          "queries at the vertices of the projected exterior-edge arrangement (object exact)",
          {ParamSpec::choice("predicates", "exact", {"exact", "double", "compare"},
                             "sign arithmetic: exact predicates, plain doubles, or both compared "
                             "(double and compare are for the stability study)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            const std::string& m = p.get_choice("predicates");
            return std::make_unique<XmpvoOrderer>(m == "exact" ? Mode::Exact
                                                  : m == "double" ? Mode::Double : Mode::Compare);
          }};
}

}  // namespace vob
