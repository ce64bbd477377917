#include "algorithms/xmpvo/bsp_xmpvo.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/xmpvo/bsp_tree.h"
#include "algorithms/xmpvo/face_pairs.h"
#include "harness/geometry/predicates.h"

namespace vob {
namespace {

using xmpvo::BspNode;
using xmpvo::BspTree;
using xmpvo::BspTriangle;
using xmpvo::ItemBox;
using xmpvo::ViewGeometry;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;

int exact_sign(const EK::FT& v) { return CGAL::sign(v) == CGAL::POSITIVE ? 1 : (CGAL::sign(v) == CGAL::NEGATIVE ? -1 : 0); }
EK::Vector_3 ev(Vec3 v) { return {v.x, v.y, v.z}; }

// Sign of det(b - a, c - a, p - q), exactly: trusted in doubles when it clears a bound far
// above the rounding of the differences, products and sums (about 8 ulps of the
// permanent), recomputed exactly otherwise.
int det_sign(Vec3 a, Vec3 b, Vec3 c, Vec3 p, Vec3 q) {
  const Vec3 u = b - a, v = c - a, w = p - q;
  const double d = u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
  const double perm = std::fabs(u.x) * (std::fabs(v.y * w.z) + std::fabs(v.z * w.y)) +
                      std::fabs(u.y) * (std::fabs(v.x * w.z) + std::fabs(v.z * w.x)) +
                      std::fabs(u.z) * (std::fabs(v.x * w.y) + std::fabs(v.y * w.x));
  if (perm > 1e-250 && std::fabs(d) > 1e-14 * perm) return d > 0 ? 1 : -1;
  const EK::Vector_3 eu = ev(b) - ev(a), evv = ev(c) - ev(a), ew = ev(p) - ev(q);
  return exact_sign(CGAL::determinant(eu, evv, ew));
}

// Sign of (p - q) . f, exactly (same scheme).
int dot_sign(Vec3 p, Vec3 q, Vec3 f) {
  const Vec3 w = p - q;
  const double d = w.x * f.x + w.y * f.y + w.z * f.z;
  const double mag = std::fabs(w.x * f.x) + std::fabs(w.y * f.y) + std::fabs(w.z * f.z);
  if (mag > 1e-250 && std::fabs(d) > 1e-14 * mag) return d > 0 ? 1 : -1;
  return exact_sign((ev(p) - ev(q)) * ev(f));
}

int sign_of_cmp(double a, double b) { return a > b ? 1 : (a < b ? -1 : 0); }

// Sign of det(b - a, c - a, p - q) for a node's plane (a, b, c), from the node's
// precomputed normal when it clears the rounding bound (as det_sign), else exactly.
int node_det_sign(const BspNode& nd, Vec3 p, Vec3 q, bool q_is_a = false) {
  const Vec3 w = p - q;
  const double d = nd.n.x * w.x + nd.n.y * w.y + nd.n.z * w.z;
  const double perm = nd.nabs.x * std::fabs(w.x) + nd.nabs.y * std::fabs(w.y) + nd.nabs.z * std::fabs(w.z);
  if (perm > 1e-250 && std::fabs(d) > 1e-14 * perm) return d > 0 ? 1 : -1;
  // q == a: an orientation of points (often exactly zero: vertices shared with the
  // splitter), which CGAL's filtered kernel settles fastest.
  if (q_is_a) return p == nd.a || p == nd.b || p == nd.c ? 0 : orient3d(nd.a, nd.b, nd.c, p);
  return det_sign(nd.a, nd.b, nd.c, p, q);
}

class BspXmpvoOrderer final : public Orderer {
 public:
  BspXmpvoOrderer(int candidates, int sample, int split_weight, bool stop) : stop_when_covered_(stop) {
    opt_.candidates = candidates;
    opt_.sample = sample;
    opt_.split_weight = split_weight;
  }
  Claims claims() const override { return mpvo::core_claims(true, false); }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    core_.prepare(scene, clock);
    { auto p = clock.phase("exterior faces"); scene.exterior_faces(); }
    auto p = clock.phase("BSP build");
    tree_ = BspTree::build(scene.exterior_faces(), opt_);
    const size_t b = tree_.triangles().size();
    facing_.assign(b, 0);
    usable_.assign(b, 0);
    stamp_.assign(b, -1);
    cell_stamp_.assign(core_.num_cells(), -1);
    node_side_.assign(tree_.nodes().size(), 0);
    complete_.assign(tree_.nodes().size(), -1);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    {
      auto p = clock.phase("create partial order");
      core_.create_partial_order(view);
    }
    Stats st;
    {
      auto p = clock.phase("tree work");
      tree_work(view, st);
    }
    {
      auto p = clock.phase("glue");
      glue(st);
    }
    {
      auto p = clock.phase("DFS");
      core_.dfs_all(out, &extra_);
    }
    core_.add_counters(out);
    auto& k = out.counters;
    const xmpvo::BspStats& bs = tree_.stats();
    k["exterior_triangles"] = static_cast<double>(bs.triangles);
    k["bsp_nodes"] = static_cast<double>(bs.nodes);
    k["bsp_depth"] = static_cast<double>(bs.depth);
    k["bsp_fragments"] = static_cast<double>(bs.fragments);
    k["bsp_splits"] = static_cast<double>(bs.splits);
    k["fragment_growth"] = bs.growth;
    k["bsp_build_seconds"] = bs.seconds;
    k["bsp_free_nodes"] = static_cast<double>(bs.free_nodes);
    k["bsp_filtered_tests"] = static_cast<double>(bs.filtered_tests);
    k["bsp_exact_tests"] = static_cast<double>(bs.exact_tests);
    k["bsp_point_tests"] = static_cast<double>(bs.point_tests);
    k["bytes_bsp"] = static_cast<double>(tree_.bytes());
    k["back_facing"] = static_cast<double>(st.back);
    k["front_facing"] = static_cast<double>(st.front);
    k["skipped_triangles"] = static_cast<double>(st.skipped);
    k["beam_queries"] = static_cast<double>(st.queries);
    k["nodes_visited"] = static_cast<double>(st.nodes);
    k["boxes_visited"] = static_cast<double>(st.boxes);
    k["candidates"] = static_cast<double>(cand_.size());
    k["overlap_tests"] = static_cast<double>(st.overlap_tests);
    k["depth_undecided"] = static_cast<double>(st.undecided);
    k["early_stops"] = static_cast<double>(st.early_stops);
    k["relations"] = static_cast<double>(pairs_.size());
    k["bytes_mpvo"] = static_cast<double>(core_.bytes());
    k["bytes_relations"] = static_cast<double>(extra_.bytes() + pairs_.capacity() * sizeof(pairs_[0]) +
                                               cand_.capacity() * sizeof(cand_[0]));
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + tree_.bytes() + extra_.bytes() + pairs_.capacity() * sizeof(pairs_[0]) +
           cand_.capacity() * sizeof(cand_[0]) + facing_.capacity() + usable_.capacity() +
           stamp_.capacity() * 4 + cell_stamp_.capacity() * 4 + node_side_.capacity() +
           stack_.capacity() * 4 + complete_.capacity() * 4 + cover_.capacity() * 4;
  }

 private:
  struct Stats {
    int64_t back = 0, front = 0, skipped = 0, queries = 0, nodes = 0, boxes = 0;
    int64_t overlap_tests = 0, undecided = 0, early_stops = 0;
  };

  // The beam of one back-facing triangle: vertices x[i] and recession directions
  // (x[i] - eye, or dir), with their per-axis sign summaries for the box test.
  struct Beam {
    const BspTriangle* t;
    Vec3 lo, hi;            // min / max of the vertices per axis
    bool dirs_nonneg[3], dirs_nonpos[3];
    int edge_side[3];       // side of x[j+2] w.r.t. edge plane (x[j], x[j+1]), nonzero
    // The beam's bounding planes in doubles, normals pointing into the beam: X's plane,
    // then the three edge planes; each through point po. For culling boxes only.
    Vec3 pn[4], po[4];
  };

  // Side of the eye (perspective) or of the direction (orthographic) w.r.t. node n's plane,
  // cached per view: 0 unknown, else sign + 2.
  int node_side(int32_t n) {
    int8_t& c = node_side_[n];
    if (c == 0) {
      const BspNode& nd = tree_.nodes()[n];
      const int v = g_.ortho ? node_det_sign(nd, g_.dir, Vec3{0, 0, 0}) : node_det_sign(nd, g_.eye, nd.a, true);
      c = static_cast<int8_t>(v + 2);
    }
    return c - 2;
  }

  // +1: the beam is in the closed positive half-space of node n's plane, -1 negative, 0
  // it crosses the plane. `near` gets the side rays come from (0 when none: the eye is in
  // the plane); `complete` whether every ray of the beam meets the plane at s >= 1 (X's
  // vertices on the closed near side, every recession direction pointing to the far side),
  // so that the beam's cross-section there is the whole of it.
  // `starts_here`: X lies in the plane, so the beam starts in it.
  int beam_vs_node(const Beam& bm, int32_t n, int& near, bool& complete, bool& starts_here) {
    const BspNode& nd = tree_.nodes()[n];
    const int e = node_side(n);
    near = g_.ortho ? -e : e;
    bool pos = true, neg = true;
    complete = near != 0;
    starts_here = true;
    for (int i = 0; i < 3; ++i) {
      const int si = node_det_sign(nd, bm.t->p[i], nd.a, true);
      starts_here &= si == 0;
      int ri;  // sign of the plane's value along the recession direction
      if (g_.ortho) {
        ri = e;
      } else if (si != e) {
        ri = si > e ? 1 : -1;  // f(x) - f(eye) has the sign of the larger sign's
      } else if (si == 0) {
        ri = 0;
      } else {
        ri = node_det_sign(nd, bm.t->p[i], g_.eye);
      }
      pos &= si >= 0 && ri >= 0;
      neg &= si <= 0 && ri <= 0;
      complete &= si * near >= 0 && ri == -near;
    }
    if (pos && !neg) return 1;
    if (neg && !pos) return -1;
    return 0;
  }

  // edge_side of face_pairs.h, with the orthographic sign taken by the filtered det_sign
  // instead of a lazy exact kernel: the same sign, det(b - a, p - a, dir).
  int edge_side(Vec3 a, Vec3 b, Vec3 p) const {
    return g_.ortho ? det_sign(a, b, p, g_.dir, Vec3{0, 0, 0}) : orient3d(g_.eye, a, b, p);
  }

  // Whether the box is separated from the beam by one of its axis planes (exact
  // comparisons), by X's plane or by one of X's edge planes (exact signs of the corners).
  bool box_separated(const Beam& bm, const ItemBox& box) const { return box_separated(bm, box.lo, box.hi); }
  bool box_separated(const Beam& bm, Vec3 blo_, Vec3 bhi_) const {
    struct {
      Vec3 lo, hi;
    } box{blo_, bhi_};
    const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    const double blo[3] = {bm.lo.x, bm.lo.y, bm.lo.z}, bhi[3] = {bm.hi.x, bm.hi.y, bm.hi.z};
    // Strict: a box touching the beam's start (coplanar faces of a touching volume) counts.
    for (int k = 0; k < 3; ++k) {
      if (bm.dirs_nonneg[k] && blo[k] > hi[k]) return true;
      if (bm.dirs_nonpos[k] && bhi[k] < lo[k]) return true;
    }
    // The box corner farthest into each bounding plane: if even it is outside by more than
    // a margin far above the rounding of the double evaluation (~1e-15 relative), the box
    // is outside that plane. Only a cull: near-zero cases go on to the exact tests.
    for (int j = 0; j < 4; ++j) {
      const Vec3 n = bm.pn[j];
      const Vec3 c{n.x > 0 ? box.hi.x : box.lo.x, n.y > 0 ? box.hi.y : box.lo.y, n.z > 0 ? box.hi.z : box.lo.z};
      const Vec3 w = c - bm.po[j];
      const double v = n.x * w.x + n.y * w.y + n.z * w.z;
      const double mag = std::fabs(n.x * w.x) + std::fabs(n.y * w.y) + std::fabs(n.z * w.z);
      if (v < -1e-12 * mag) return true;
    }
    return false;
  }

  // Whether X's plane or one of its edge planes separates triangle Y from X's beam. A Y in
  // X's plane is not separated by it: the beam starts there (a volume touching X's).
  bool separated(const Beam& bm, const BspTriangle& y) const {
    const BspTriangle& x = *bm.t;
    bool behind = false, in_plane = true;
    for (int k = 0; k < 3; ++k) {
      const int s = orient3d(x.p[0], x.p[1], x.p[2], y.p[k]);
      behind |= s > 0;
      in_plane &= s == 0;
    }
    if (!behind && !in_plane) return true;
    for (int j = 0; j < 3; ++j) {
      const Vec3 a = x.p[j], b = x.p[(j + 1) % 3];
      bool inside = false;
      for (int k = 0; k < 3 && !inside; ++k) inside = edge_side(a, b, y.p[k]) * bm.edge_side[j] > 0;
      if (!inside) return true;
    }
    return false;
  }

  void consider(const Beam& bm, int32_t xi, int32_t yi) {
    if (stamp_[yi] == xi) return;
    stamp_[yi] = xi;
    const BspTriangle& y = tree_.triangles()[yi];
    if (facing_[yi] <= 0 || !usable_[yi]) return;
    if (separated(bm, y)) return;
    // A split triangle reaches beyond this node's region, where BSP order says nothing.
    if (tree_.unsplit(yi)) cover_.push_back(yi);
    if (y.cell != bm.t->cell) cand_.emplace_back(xi, yi);
  }

  // Whether the coplanar front-facing triangles cover_ (those of one node not separated from
  // the beam and never split, so lying in the node's region) cover the beam's whole cross-section C at their plane, exactly: no boundary
  // edge of their union (an edge not shared, reversed, by another of them) meets the open
  // cone of X (2-D separation in projection: one of X's edge planes, or the plane through the
  // eye and the edge, has the edge resp. X on one closed side), and one of them overlaps X
  // in projection. C is convex, so it then lies in the union.
  bool covered(const Beam& bm) const {
    const size_t m = cover_.size();
    if (m == 0 || m > 64) return false;
    const auto& tris = tree_.triangles();
    const Vec3* x = bm.t->p;
    for (size_t a = 0; a < m; ++a) {
      const BspTriangle& ta = tris[cover_[a]];
      for (int k = 0; k < 3; ++k) {
        const Vec3 p = ta.p[k], q = ta.p[(k + 1) % 3];
        bool shared = false;
        for (size_t c = 0; c < m && !shared; ++c) {
          if (c == a) continue;
          const BspTriangle& tc = tris[cover_[c]];
          for (int l = 0; l < 3 && !shared; ++l) shared = tc.p[l] == q && tc.p[(l + 1) % 3] == p;
        }
        if (shared) continue;
        bool apart = false;
        for (int j = 0; j < 3 && !apart; ++j)
          apart = edge_side(x[j], x[(j + 1) % 3], p) * bm.edge_side[j] <= 0 &&
                  edge_side(x[j], x[(j + 1) % 3], q) * bm.edge_side[j] <= 0;
        if (!apart) {
          const int s0 = edge_side(p, q, x[0]), s1 = edge_side(p, q, x[1]), s2 = edge_side(p, q, x[2]);
          apart = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
        }
        if (!apart) return false;
      }
    }
    for (int32_t y : cover_)
      if (xmpvo::projections_overlap(g_, x, 3, tris[y].p, 3)) return true;
    return false;
  }

  void tree_work(const Camera& view, Stats& st) {
    g_ = ViewGeometry::of(view);
    const Vec3 fwd = view.forward();
    const auto& tris = tree_.triangles();
    const int32_t b = static_cast<int32_t>(tris.size());
    for (int32_t i = 0; i < b; ++i) {
      const BspTriangle& t = tris[i];
      facing_[i] = static_cast<int8_t>(xmpvo::eye_side(g_, t.p[0], t.p[1], t.p[2]));
      bool ok = true;
      if (!g_.ortho)
        for (int k = 0; k < 3 && ok; ++k) ok = dot_sign(t.p[k], view.eye, fwd) > 0;
      usable_[i] = ok;
      st.skipped += !ok;
      st.back += facing_[i] < 0, st.front += facing_[i] > 0;
    }
    std::fill(stamp_.begin(), stamp_.end(), -1);
    std::fill(node_side_.begin(), node_side_.end(), 0);
    cand_.clear();
    if (tree_.root() < 0) return;
    const auto& nodes = tree_.nodes();
    const auto& items = tree_.items();
    const auto& boxes = tree_.boxes();
    std::vector<int32_t> box_stack;
    for (int32_t xi = 0; xi < b; ++xi) {
      if (facing_[xi] >= 0 || !usable_[xi]) continue;
      ++st.queries;
      Beam bm;
      bm.t = &tris[xi];
      const Vec3* x = bm.t->p;
      bm.lo = bm.hi = x[0];
      for (int i = 1; i < 3; ++i) {
        bm.lo = {std::min(bm.lo.x, x[i].x), std::min(bm.lo.y, x[i].y), std::min(bm.lo.z, x[i].z)};
        bm.hi = {std::max(bm.hi.x, x[i].x), std::max(bm.hi.y, x[i].y), std::max(bm.hi.z, x[i].z)};
      }
      for (int k = 0; k < 3; ++k) bm.dirs_nonneg[k] = bm.dirs_nonpos[k] = true;
      for (int i = 0; i < 3; ++i) {
        const double xc[3] = {x[i].x, x[i].y, x[i].z};
        const double ec[3] = {g_.eye.x, g_.eye.y, g_.eye.z}, dc[3] = {g_.dir.x, g_.dir.y, g_.dir.z};
        for (int k = 0; k < 3; ++k) {
          const int s = g_.ortho ? sign_of_cmp(dc[k], 0.0) : sign_of_cmp(xc[k], ec[k]);
          bm.dirs_nonneg[k] &= s >= 0;
          bm.dirs_nonpos[k] &= s <= 0;
        }
      }
      for (int j = 0; j < 3; ++j) bm.edge_side[j] = edge_side(x[j], x[(j + 1) % 3], x[(j + 2) % 3]);
      // X is back-facing: the beam lies on its normal's side.
      bm.pn[0] = cross(x[1] - x[0], x[2] - x[0]);
      bm.po[0] = x[0];
      for (int j = 0; j < 3; ++j) {
        const Vec3 a = x[j], b2 = x[(j + 1) % 3];
        // (a - eye) x (b - a), not (a - eye) x (b - eye): the same normal, but two long
        // nearly parallel vectors of a far eye cancel to a few digits (the cull below then
        // separated boxes the beam meets); one long and one short vector keep full precision.
        const Vec3 n = g_.ortho ? cross(g_.dir, b2 - a) : cross(a - g_.eye, b2 - a);
        bm.pn[j + 1] = n * static_cast<double>(bm.edge_side[j]);
        bm.po[j + 1] = g_.ortho ? a : g_.eye;
      }
      // Front to back: near subtree, the node's items, far subtree. Entries are node ids;
      // ~n marks "the items of node n".
      stack_.clear();
      stack_.push_back(tree_.root());
      while (!stack_.empty()) {
        const int32_t e = stack_.back();
        stack_.pop_back();
        if (e >= 0) {
          const BspNode& node = nodes[e];
          if (box_separated(bm, node.lo, node.hi)) continue;
          ++st.nodes;
          int near;
          bool complete, starts_here;
          const int side = beam_vs_node(bm, e, near, complete, starts_here);
          if (side != 0) {
            const int32_t child = side > 0 ? node.front : node.back;
            if (child >= 0) stack_.push_back(child);
            // X in the node's plane: the coplanar items are at X's depth, before the far side
            // (front-facing ones are where a touching volume begins).
            if (starts_here && node.count > 0) {
              stack_.push_back(~e);
              complete_[e] = complete ? xi : -1;
            }
            continue;
          }
          const int32_t first = near >= 0 ? node.front : node.back;
          const int32_t last = near >= 0 ? node.back : node.front;
          if (last >= 0) stack_.push_back(last);
          if (node.count > 0) stack_.push_back(~e);
          complete_[e] = complete ? xi : -1;
          if (first >= 0) stack_.push_back(first);
          continue;
        }
        const int32_t n = ~e;
        const BspNode& node = nodes[n];
        cover_.clear();
        if (node.boxes < 0) {
          for (int32_t i = node.first; i < node.first + node.count; ++i) consider(bm, xi, items[i]);
        } else {
          box_stack.assign(1, node.boxes);
          while (!box_stack.empty()) {
            const ItemBox& box = boxes[box_stack.back()];
            box_stack.pop_back();
            ++st.boxes;
            if (box_separated(bm, box)) continue;
            if (box.left >= 0) {
              box_stack.push_back(box.left);
              box_stack.push_back(box.left + 1);
            } else {
              for (int32_t i = box.first; i < box.first + box.count; ++i) consider(bm, xi, items[i]);
            }
          }
        }
        // Every ray of the beam enters the mesh at this plane or before: what lies later in
        // front-to-back order is behind on every ray and cannot be the first entry after X.
        if (stop_when_covered_ && complete_[n] == xi && covered(bm)) {
          ++st.early_stops;
          stack_.clear();
        }
      }
    }
  }

  void glue(Stats& st) {
    const auto& tris = tree_.triangles();
    pairs_.clear();
    std::fill(cell_stamp_.begin(), cell_stamp_.end(), -1);
    for (const auto& [xi, yi] : cand_) {
      const BspTriangle& x = tris[xi];
      const BspTriangle& y = tris[yi];
      if (cell_stamp_[y.cell] == xi) continue;  // this X already orders that cell
      ++st.overlap_tests;
      if (!xmpvo::projections_overlap(g_, x.p, 3, y.p, 3)) continue;
      const int d = xmpvo::depth_order(g_, x.p, 3, y.p, 3);
      if (d == 0) ++st.undecided;
      if (d != -1) continue;
      cell_stamp_[y.cell] = xi;
      pairs_.emplace_back(x.cell, y.cell);
    }
    mpvo::sort_unique_pairs(pairs_, core_.num_cells());
    extra_.build_from_pairs(core_.num_cells(), pairs_);
  }

  xmpvo::BspOptions opt_;
  mpvo::MpvoCore core_;
  BspTree tree_;
  ViewGeometry g_;
  std::vector<int8_t> facing_;   // per triangle: eye_side, per view
  std::vector<uint8_t> usable_;  // per triangle: entirely in front of a perspective eye
  std::vector<int32_t> stamp_;   // per triangle: last beam that considered it
  std::vector<int32_t> cell_stamp_;  // per cell: last beam that related it
  std::vector<int8_t> node_side_;
  std::vector<int32_t> stack_;   // traversal: node ids, ~n for a node's items
  std::vector<int32_t> complete_;  // per node: the beam whose cross-section there is complete
  std::vector<int32_t> cover_;     // front-facing items of one node meeting the beam
  bool stop_when_covered_;
  std::vector<std::pair<int32_t, int32_t>> cand_;   // (X, Y) triangles
  std::vector<std::pair<int32_t, int32_t>> pairs_;  // (front cell, behind cell)
  mpvo::ExtraRelations extra_;
};

}  // namespace

OrdererInfo bsp_xmpvo_orderer_info() {
  return {"bsp-xmpvo", SceneKind::Cells,
          "Comba et al.'s BSP-XMPVO: MPVO arrows plus exterior-cell relations from a BSP tree of "
          "the exterior faces, exact at object precision",
          {ParamSpec::integer("candidates", 5, 1, 64, "splitters tried per BSP node"),
           ParamSpec::integer("sample", 64, 1, 100000, "fragments each candidate is scored on"),
           ParamSpec::integer("split_weight", 8, 0, 1000, "score = split_weight * splits + |front - back|"),
           ParamSpec::boolean("stop", true, "end a beam's traversal once its cross-section is proved covered")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<BspXmpvoOrderer>(p.get_int("candidates"), p.get_int("sample"),
                                                     p.get_int("split_weight"), p.get_bool("stop"));
          }};
}

}  // namespace vob
