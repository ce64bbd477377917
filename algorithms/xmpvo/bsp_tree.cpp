#include "algorithms/xmpvo/bsp_tree.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "algorithms/xmpvo/bsp_fragment.h"
#include "harness/geometry/predicates.h"
#include "harness/scene/space_curve.h"

namespace vob::xmpvo {
namespace {

using bsp::Frag;
using bsp::FragmentOps;
using bsp::PlaneTable;
using K = CGAL::Epeck;
using P3 = K::Point_3;
using FT = K::FT;

P3 ep(Vec3 v) { return P3(v.x, v.y, v.z); }

int sgn(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0); }

struct Work {
  int32_t node;
  int32_t depth;
  std::vector<Frag> frags;
};

// An axis-aligned plane through a median of the triangles' centroids (of a sample of the
// fragments) across their widest extent: the plane x = c is orient3d-positive for x > c.
int32_t median_plane(const std::vector<Frag>& frags, const std::vector<BspTriangle>& tris, int64_t stride,
                     PlaneTable& planes) {
  std::vector<Vec3> cs;
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi = lo * -1.0;
  for (size_t i = 0; i < frags.size(); i += stride) {
    const BspTriangle& t = tris[frags[i].tri];
    const Vec3 c = (t.p[0] + t.p[1] + t.p[2]) * (1.0 / 3);
    cs.push_back(c);
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  const Vec3 e = hi - lo;
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  std::nth_element(cs.begin(), cs.begin() + cs.size() / 2, cs.end(),
                   [axis](Vec3 p, Vec3 q) { return p[axis] < q[axis]; });
  const double c = cs[cs.size() / 2][axis];
  if (axis == 0) return planes.add({c, 0, 0}, {c, 1, 0}, {c, 0, 1});
  if (axis == 1) return planes.add({0, c, 0}, {0, c, 1}, {1, c, 0});
  return planes.add({0, 0, c}, {1, 0, c}, {0, 1, c});
}

// The splitting plane of a node (an id of `planes`): the best of a few evenly spaced
// triangle planes and, with free_planes, one median plane, scored on a sample of the
// fragments by split_weight * splits + |front - back|. Scores are guesses in doubles
// (FragmentOps::guess_side): they choose a plane, exact sides then split by it.
struct Choice {
  int32_t plane;     // the choice
  int32_t triangle;  // the best triangle plane (the choice unless that is a free plane)
};
struct Sample {  // the sampled fragments' approximate points, gathered once per node
  std::vector<int32_t> frag, start;
  std::vector<Vec3> pts;
};
Choice choose_plane(const std::vector<Frag>& frags, const std::vector<BspTriangle>& tris, const FragmentOps& ops,
                    const BspOptions& opt, PlaneTable& planes, Sample& smp, std::vector<int>& s) {
  const int64_t m = static_cast<int64_t>(frags.size());
  int32_t best = frags[0].tri;
  if (m <= 1 || opt.candidates <= 1) return {best, best};
  const int cands = static_cast<int>(std::min<int64_t>(opt.candidates, m));
  const int64_t stride = std::max<int64_t>(1, m / std::max(opt.sample, 1));
  smp.frag.clear(), smp.start.clear(), smp.pts.clear();
  for (int64_t i = 0; i < m; i += stride) {
    smp.frag.push_back(static_cast<int32_t>(i));
    smp.start.push_back(static_cast<int32_t>(smp.pts.size()));
    ops.approx_points(frags[i], smp.pts);
  }
  smp.start.push_back(static_cast<int32_t>(smp.pts.size()));
  const int64_t samples = static_cast<int64_t>(smp.frag.size());
  int64_t best_score = -1;
  bool both = false;  // the last scored plane has sample fragments strictly on each side
  // A candidate's score, or a value >= best_score as soon as even the rest of the sample
  // could not bring it below (the choice is the same, for less work).
  auto score = [&](int32_t h) -> int64_t {
    int64_t front = 0, back = 0, splits = 0;
    for (int64_t j = 0; j < samples; ++j) {
      const bsp::Side sd = ops.guess_side(h, frags[smp.frag[j]], &smp.pts[smp.start[j]], s);
      front += sd == bsp::kFront, back += sd == bsp::kBack, splits += sd == bsp::kSplit;
      if (best_score >= 0 && opt.split_weight * splits + std::llabs(front - back) - (samples - j - 1) >= best_score) {
        both = false;
        return best_score;
      }
    }
    both = front > 0 && back > 0;
    return opt.split_weight * splits + std::llabs(front - back);
  };
  for (int c = 0; c < cands; ++c) {
    const int32_t cand = frags[(c * m) / cands + (m > cands ? (c * 7919) % (m / cands) : 0)].tri;
    const int64_t sc = score(cand);
    if (best_score < 0 || sc < best_score) best_score = sc, best = cand;
  }
  if (opt.free_planes) {
    const int32_t size = planes.size();
    const int32_t h = median_plane(frags, tris, stride, planes);
    // A free plane holds no fragment: it must leave one out of each child.
    if (score(h) < best_score && both) return {h, best};
    planes.truncate(size);
  }
  return {best, best};
}

// Whether exact sides put fragments into both children of plane h (a guessed free plane
// must, or the node would make no progress).
bool divides(const std::vector<Frag>& frags, int32_t h, const FragmentOps& ops, std::vector<int>& s) {
  bool front = false, back = false;
  for (const Frag& f : frags) {
    const bsp::Side sd = FragmentOps::side_of(s.data(), ops.classify(h, f, s));
    front |= sd == bsp::kFront || sd == bsp::kSplit;
    back |= sd == bsp::kBack || sd == bsp::kSplit;
    if (front && back) return true;
  }
  return false;
}

}  // namespace

struct BspTree::Exact {
  struct Stored {
    int32_t node, tri;
    std::vector<P3> poly;
  };
  std::vector<Stored> frags;
};

BspTree::BspTree() = default;
BspTree::~BspTree() = default;
BspTree::BspTree(BspTree&&) noexcept = default;
BspTree& BspTree::operator=(BspTree&&) noexcept = default;

size_t BspTree::bytes() const {
  return tris_.capacity() * sizeof(BspTriangle) + nodes_.capacity() * sizeof(BspNode) +
         items_.capacity() * sizeof(int32_t) + boxes_.capacity() * sizeof(ItemBox) +
         parent_.capacity() * sizeof(int32_t) + unsplit_.capacity();
}

BspTree BspTree::build(const ExteriorFaces& exterior, const BspOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  BspTree t;
  std::vector<BspTriangle> input;
  std::vector<int32_t> input_vid;  // per triangle, its vertices' ids in exterior.points
  Aabb box;
  for (size_t i = 0; i < exterior.face.size(); ++i) {
    const Vec3* v = &exterior.corners[4 * i];
    const int32_t* id = &exterior.vertex[4 * i];
    for (int k = 1; k + 1 < exterior.size[i]; ++k) {
      input.push_back({{v[0], v[k], v[k + 1]}, exterior.face[i], exterior.cell[i]});
      input_vid.insert(input_vid.end(), {id[0], id[k], id[k + 1]});
      for (const Vec3& p : input.back().p) box.add(p);
    }
  }
  // Triangles in Hilbert order of their centroids and points numbered by first use: a
  // node's fragments then lie close together in memory, and so do their vertices' memo
  // entries (meshers number boundary faces in no spatial order).
  std::vector<std::pair<uint64_t, int32_t>> order(input.size());
  for (size_t i = 0; i < input.size(); ++i) {
    const Vec3* p = input[i].p;
    order[i] = {hilbert_code((p[0] + p[1] + p[2]) * (1.0 / 3), box), static_cast<int32_t>(i)};
  }
  std::sort(order.begin(), order.end());
  std::vector<int32_t> vid, point_id(exterior.points.size(), -1);
  int32_t points = 0;
  for (const auto& [code, i] : order) {
    t.tris_.push_back(input[i]);
    for (int k = 0; k < 3; ++k) {
      int32_t& id = point_id[input_vid[3 * static_cast<size_t>(i) + k]];
      if (id < 0) id = points++;
      vid.push_back(id);
    }
  }
  if (opt.keep_fragments) t.exact_ = std::make_unique<Exact>();
  const int32_t b = static_cast<int32_t>(t.tris_.size());
  t.stats_.triangles = b;
  PlaneTable planes;  // plane i is triangle i's; free planes follow
  for (const BspTriangle& tr : t.tris_) planes.add(tr.p[0], tr.p[1], tr.p[2]);
  const FragmentOps ops(t.tris_, vid, points, planes);
  std::vector<int32_t> node_plane;
  if (b > 0) {
    // Explicit stack: degenerate inputs can make the tree as deep as b.
    std::vector<Work> stack;
    Work root{0, 1, {}};
    root.frags.reserve(b);
    for (int32_t i = 0; i < b; ++i) root.frags.push_back(Frag{i, true, {}});
    t.nodes_.push_back({});
    t.parent_.push_back(-1);
    node_plane.push_back(-1);
    stack.push_back(std::move(root));
    std::vector<int32_t> coplanar;
    std::vector<int> s;
    Sample sample;
    while (!stack.empty()) {
      Work w = std::move(stack.back());
      stack.pop_back();
      t.stats_.depth = std::max<int64_t>(t.stats_.depth, w.depth);
      const Choice choice = choose_plane(w.frags, t.tris_, ops, opt, planes, sample, s);
      int32_t h = choice.plane;
      if (h != choice.triangle && !divides(w.frags, h, ops, s)) {
        planes.truncate(h);  // the free plane is the table's last
        h = choice.triangle;
        ++t.stats_.free_refused;
      }
      std::vector<Frag> front, back;
      coplanar.clear();
      for (Frag& f : w.frags) {
        const int n = ops.classify(h, f, s);
        switch (FragmentOps::side_of(s.data(), n)) {
          case bsp::kCoplanar:
            coplanar.push_back(f.tri);
            if (t.exact_) t.exact_->frags.push_back({w.node, f.tri, ops.exact_polygon(f)});
            break;
          case bsp::kFront: front.push_back(std::move(f)); break;
          case bsp::kBack: back.push_back(std::move(f)); break;
          case bsp::kSplit: {
            Frag a, c;
            ops.split(h, f, s.data(), n, a, c);
            front.push_back(std::move(a));
            back.push_back(std::move(c));
            ++t.stats_.splits;
            break;
          }
        }
      }
      w.frags.clear();
      w.frags.shrink_to_fit();
      BspNode& node = t.nodes_[w.node];
      node_plane[w.node] = h;
      node.splitter = h < b ? h : -1;
      t.stats_.free_nodes += h >= b;
      node.first = static_cast<int32_t>(t.items_.size());
      node.count = static_cast<int32_t>(coplanar.size());
      t.items_.insert(t.items_.end(), coplanar.begin(), coplanar.end());
      t.stats_.fragments += static_cast<int64_t>(coplanar.size());
      for (int side = 0; side < 2; ++side) {
        std::vector<Frag>& list = side == 0 ? front : back;
        if (list.empty()) continue;
        const int32_t child = static_cast<int32_t>(t.nodes_.size());
        (side == 0 ? t.nodes_[w.node].front : t.nodes_[w.node].back) = child;
        t.nodes_.push_back({});
        t.parent_.push_back(w.node);
        node_plane.push_back(-1);
        stack.push_back(Work{child, w.depth + 1, std::move(list)});
      }
    }
  }
  // Item box hierarchies: median split on the longest axis of the centroids' box.
  for (BspNode& node : t.nodes_) {
    if (node.count <= kLeafItems) continue;
    node.boxes = static_cast<int32_t>(t.boxes_.size());
    t.boxes_.push_back({{}, {}, -1, node.first, node.count});
    std::vector<int32_t> todo = {node.boxes};
    while (!todo.empty()) {
      const int32_t bi = todo.back();
      todo.pop_back();
      ItemBox box = t.boxes_[bi];
      Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      Vec3 clo = lo, chi = hi;
      for (int32_t i = box.first; i < box.first + box.count; ++i) {
        const BspTriangle& tr = t.tris_[t.items_[i]];
        for (const Vec3& p : tr.p) {
          lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
          hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
        const Vec3 c = (tr.p[0] + tr.p[1] + tr.p[2]) * (1.0 / 3);
        clo = {std::min(clo.x, c.x), std::min(clo.y, c.y), std::min(clo.z, c.z)};
        chi = {std::max(chi.x, c.x), std::max(chi.y, c.y), std::max(chi.z, c.z)};
      }
      box.lo = lo, box.hi = hi;
      if (box.count > kLeafItems) {
        const Vec3 e = chi - clo;
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        auto key = [&](int32_t id) {
          const BspTriangle& tr = t.tris_[id];
          const Vec3 c = tr.p[0] + tr.p[1] + tr.p[2];
          return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
        };
        const int32_t half = box.count / 2;
        std::nth_element(t.items_.begin() + box.first, t.items_.begin() + box.first + half,
                         t.items_.begin() + box.first + box.count,
                         [&](int32_t a, int32_t b2) { return key(a) < key(b2); });
        box.left = static_cast<int32_t>(t.boxes_.size());
        t.boxes_.push_back({{}, {}, -1, box.first, half});
        t.boxes_.push_back({{}, {}, -1, box.first + half, box.count - half});
        todo.push_back(box.left);
        todo.push_back(box.left + 1);
      }
      t.boxes_[bi] = box;
    }
  }
  for (size_t i = 0; i < t.nodes_.size(); ++i) {
    BspNode& node = t.nodes_[i];
    const Vec3* sp = planes.points(node_plane[i]);
    const Vec3 u = sp[1] - sp[0], v = sp[2] - sp[0];
    node.a = sp[0], node.b = sp[1], node.c = sp[2];
    node.n = cross(u, v);
    node.nabs = {std::fabs(u.y * v.z) + std::fabs(u.z * v.y), std::fabs(u.x * v.z) + std::fabs(u.z * v.x),
                 std::fabs(u.x * v.y) + std::fabs(u.y * v.x)};
  }
  std::vector<int32_t> count(b, 0);
  for (int32_t i : t.items_) ++count[i];
  t.unsplit_.resize(b);
  for (int32_t i = 0; i < b; ++i) t.unsplit_[i] = count[i] == 1;
  // Subtree boxes, children first (a child's id is larger than its parent's).
  for (size_t n = t.nodes_.size(); n-- > 0;) {
    BspNode& node = t.nodes_[n];
    Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    auto grow = [&](Vec3 a, Vec3 c) {
      lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
      hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    };
    for (int32_t i = node.first; i < node.first + node.count; ++i)
      for (const Vec3& p : t.tris_[t.items_[i]].p) grow(p, p);
    for (int32_t c : {node.front, node.back})
      if (c >= 0) grow(t.nodes_[c].lo, t.nodes_[c].hi);
    node.lo = lo, node.hi = hi;
  }
  t.stats_.nodes = static_cast<int64_t>(t.nodes_.size());
  t.stats_.filtered_tests = ops.filtered_tests();
  t.stats_.exact_tests = ops.exact_tests();
  t.stats_.point_tests = planes.exact_point_tests();
  t.stats_.growth = b ? static_cast<double>(t.stats_.fragments) / b : 0.0;
  t.stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

std::string BspTree::check_invariants() const {
  if (!exact_) return "tree built without keep_fragments";
  const int32_t b = static_cast<int32_t>(tris_.size());
  std::vector<FT> area(b, FT(0));
  std::vector<int> count(b, 0);
  auto axis_of = [&](int32_t tri) {
    const Vec3 n = cross(tris_[tri].p[1] - tris_[tri].p[0], tris_[tri].p[2] - tris_[tri].p[0]);
    const double x = std::fabs(n.x), y = std::fabs(n.y), z = std::fabs(n.z);
    return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
  };
  // Twice the signed area of the polygon projected along `axis`.
  auto area2 = [](const std::vector<P3>& poly, int axis) {
    FT a(0);
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
      const P3& p = poly[i];
      const P3& q = poly[(i + 1) % n];
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      a += p[u] * q[v] - p[v] * q[u];
    }
    return a;
  };
  for (const Exact::Stored& f : exact_->frags) {
    const std::string where = "fragment of triangle " + std::to_string(f.tri) + " at node " + std::to_string(f.node);
    if (f.poly.size() < 3) return where + ": fewer than 3 vertices";
    const BspTriangle& own = tris_[f.tri];
    const BspNode& at = nodes_[f.node];
    for (const P3& p : f.poly) {
      if (CGAL::orientation(ep(own.p[0]), ep(own.p[1]), ep(own.p[2]), p) != CGAL::COPLANAR)
        return where + ": off its triangle's plane";
      if (CGAL::orientation(ep(at.a), ep(at.b), ep(at.c), p) != CGAL::COPLANAR) return where + ": off its node's plane";
    }
    bool listed = false;
    for (int32_t i = nodes_[f.node].first; i < nodes_[f.node].first + nodes_[f.node].count; ++i)
      listed |= items_[i] == f.tri;
    if (!listed) return where + ": not among the node's items";
    for (int32_t child = f.node, up = parent_[f.node]; up >= 0; child = up, up = parent_[up]) {
      const BspNode& h = nodes_[up];
      const int want = h.front == child ? 1 : -1;
      for (const P3& p : f.poly)
        if (sgn(CGAL::orientation(ep(h.a), ep(h.b), ep(h.c), p)) == -want)
          return where + ": on the wrong side of ancestor " + std::to_string(up);
    }
    area[f.tri] += area2(f.poly, axis_of(f.tri));
    ++count[f.tri];
  }
  for (int32_t i = 0; i < b; ++i) {
    if (count[i] == 0) return "triangle " + std::to_string(i) + " has no fragment";
    std::vector<P3> whole = {ep(tris_[i].p[0]), ep(tris_[i].p[1]), ep(tris_[i].p[2])};
    if (area[i] != area2(whole, axis_of(i)))
      return "fragments of triangle " + std::to_string(i) + " do not cover it";
  }
  return "";
}

}  // namespace vob::xmpvo
