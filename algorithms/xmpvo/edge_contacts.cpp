#include "algorithms/xmpvo/edge_contacts.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <CGAL/Box_intersection_d/Box_d.h>
#include <CGAL/box_intersection_d.h>

#include "harness/geometry/predicates.h"

namespace vob::xmpvo {
namespace {

using BoxBase = CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_NONE>;

// A closed box that knows its edge or face.
struct IdBox : BoxBase {
  IdBox(const CGAL::Bbox_3& b, int32_t i) : BoxBase(b), item(i) {}
  std::size_t id() const { return std::size_t(item); }
  int32_t item;
};

CGAL::Bbox_3 box_of(const Vec3& p) { return CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z); }

double coord(const Vec3& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; }

// In a plane holding the segment and the triangle: whether the open segment (P, Q) meets
// the closed triangle (a, b, c), decided in the projection along a coordinate axis that
// keeps the triangle non-degenerate (orientations there are the plane's, up to one sign).
// shared[k]: vertex k of the triangle is P or Q.
bool meets_in_plane(const Vec3& P, const Vec3& Q, const Vec3* t, const bool* shared) {
  int u = 0, v = 1, s = 0;
  for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
    s = orient2d(coord(t[0], i), coord(t[0], j), coord(t[1], i), coord(t[1], j), coord(t[2], i), coord(t[2], j));
    if (s != 0) { u = i, v = j; break; }
  }
  if (s == 0) return true;  // a degenerate triangle: count it
  const auto o = [&](const Vec3& x, const Vec3& y, const Vec3& z) {
    return orient2d(coord(x, u), coord(x, v), coord(y, u), coord(y, v), coord(z, u), coord(z, v));
  };
  // A triangle edge's line with the segment on its closed outer side, touching it at most
  // at an endpoint, separates them.
  for (int k = 0; k < 3; ++k) {
    const Vec3 &x = t[k], &y = t[(k + 1) % 3];
    const int op = s * o(x, y, P), oq = s * o(x, y, Q);
    if ((op < 0 && oq <= 0) || (op <= 0 && oq < 0)) return false;
    if (op == 0 && oq == 0) {
      // Along that edge's line: the open interval (P, Q) against the closed [x, y], on a
      // coordinate where x and y differ.
      const int c = coord(x, u) != coord(y, u) ? u : v;
      const double plo = std::min(coord(P, c), coord(Q, c)), phi = std::max(coord(P, c), coord(Q, c));
      const double tlo = std::min(coord(x, c), coord(y, c)), thi = std::max(coord(x, c), coord(y, c));
      return plo < thi && tlo < phi;
    }
  }
  // The segment's line with every vertex the segment does not end at strictly on one side.
  int pos = 0, neg = 0, zero = 0;
  for (int k = 0; k < 3; ++k) {
    if (shared[k]) continue;
    const int ok = o(P, Q, t[k]);
    pos += ok > 0, neg += ok < 0, zero += ok == 0;
  }
  return zero > 0 || (pos > 0 && neg > 0);
}

// Whether the open segment (p, q) meets triangle f (closed), given that f does not have
// both p and q. Conservative where f touches only an endpoint of the segment it does not
// have, or its line only at one of its vertices (true either way).
bool meets(const ExteriorFaces& ext, int32_t p, int32_t q, int32_t f) {
  const int32_t* v = &ext.vertex[4 * static_cast<size_t>(f)];
  const Vec3 t[3] = {ext.points[v[0]], ext.points[v[1]], ext.points[v[2]]};
  const Vec3 &P = ext.points[p], &Q = ext.points[q];
  const bool shared[3] = {v[0] == p || v[0] == q, v[1] == p || v[1] == q, v[2] == p || v[2] == q};
  const bool has_p = v[0] == p || v[1] == p || v[2] == p, has_q = v[0] == q || v[1] == q || v[2] == q;
  // An endpoint the face has lies in its plane: no need to ask (a zero costs the exact path).
  const int sp = has_p ? 0 : orient3d(t[0], t[1], t[2], P);
  const int sq = has_q ? 0 : orient3d(t[0], t[1], t[2], Q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) return meets_in_plane(P, Q, t, shared);
  // The segment meets the plane at one point only: at a vertex the face has, not inside.
  if ((sp == 0 && has_p) || (sq == 0 && has_q)) return false;
  // That point lies in the closed triangle exactly when the line's orientations with the
  // triangle's edges do not disagree.
  const int t1 = orient3d(P, Q, t[0], t[1]), t2 = orient3d(P, Q, t[1], t[2]), t3 = orient3d(P, Q, t[2], t[0]);
  return !((t1 > 0 || t2 > 0 || t3 > 0) && (t1 < 0 || t2 < 0 || t3 < 0));
}

}  // namespace

EdgeContacts find_edge_contacts(const ExteriorFaces& ext) {
  EdgeContacts r;
  const size_t nf = ext.face.size();
  for (size_t f = 0; f < nf; ++f) r.triangles_only &= ext.size[f] == 3;
  if (!r.triangles_only) return r;
  std::vector<std::pair<int32_t, int32_t>> edges;
  edges.reserve(3 * nf);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = ext.vertex[4 * f + k], b = ext.vertex[4 * f + (k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  r.edges = static_cast<int64_t>(edges.size());
  std::vector<IdBox> eb, fb;
  eb.reserve(edges.size());
  fb.reserve(nf);
  for (size_t e = 0; e < edges.size(); ++e)
    eb.emplace_back(box_of(ext.points[edges[e].first]) + box_of(ext.points[edges[e].second]), int32_t(e));
  for (size_t f = 0; f < nf; ++f) {
    CGAL::Bbox_3 b;
    for (int k = 0; k < 3; ++k) b += box_of(ext.points[ext.vertex[4 * f + k]]);
    fb.emplace_back(b, int32_t(f));
  }
  std::vector<uint8_t> touched(edges.size(), 0);
  // Cutoff 1000: 107-118 ms on the 200k-cell helix, against 296 at CGAL's default of 10
  // (186-211 at 100, 130-141 at 4000).
  CGAL::box_intersection_d(
      eb.begin(), eb.end(), fb.begin(), fb.end(),
      [&](const IdBox& e, const IdBox& f) {
        ++r.candidates;
        const auto [p, q] = edges[e.item];
        const int32_t* v = &ext.vertex[4 * static_cast<size_t>(f.item)];
        const int shared = (v[0] == p || v[1] == p || v[2] == p) + (v[0] == q || v[1] == q || v[2] == q);
        if (shared < 2 && !touched[e.item] && meets(ext, p, q, f.item)) touched[e.item] = 1;
      },
      CGAL::Box_intersection_d::Box_traits_d<IdBox>(), std::ptrdiff_t(1000), CGAL::Box_intersection_d::CLOSED);
  for (const uint8_t t : touched) r.touched_edges += t;
  return r;
}

}  // namespace vob::xmpvo
