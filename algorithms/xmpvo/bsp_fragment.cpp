#include "algorithms/xmpvo/bsp_fragment.h"

#include "harness/geometry/predicates.h"

namespace vob::xmpvo::bsp {
namespace {

using K = CGAL::Epeck;
using P3 = K::Point_3;

P3 ep(Vec3 v) { return P3(v.x, v.y, v.z); }
K::Vector_3 ev(Vec3 v) { return K::Vector_3(v.x, v.y, v.z); }
K::Vector_3 normal(const Vec3* p) { return CGAL::cross_product(ev(p[1]) - ev(p[0]), ev(p[2]) - ev(p[0])); }

}  // namespace

// orient3d of vertex k of triangle tri, once per point and plane (a point is in about six
// triangles): a point of the plane's own triple (shared by neighbours, the common exact
// zero) without arithmetic, most others by the double filter, the rest exactly.
int FragmentOps::side(int32_t h, int32_t tri, int k) const {
  const int32_t v = vid_[3 * static_cast<size_t>(tri) + k];
  const int64_t tag = planes_.tag(h);
  const uint32_t m = memo_[v];
  if (m >> 2 == static_cast<uint64_t>(tag)) return static_cast<int>(m & 3) - 1;
  const Vec3 p = tris_[tri].p[k];
  const Vec3* q = planes_.points(h);
  int r = p == q[0] || p == q[1] || p == q[2] ? 0 : planes_.point_side_filtered(h, p);
  if (r == 2) {
    // Near-coplanar neighbours (TetGen's Steiner points on one input facet) come back to
    // the same few point-plane pairs many times.
    const auto [it, fresh] = exact_memo_.try_emplace((static_cast<uint64_t>(tag) << 32) | static_cast<uint32_t>(v), 0);
    if (fresh) it->second = static_cast<int8_t>(planes_.point_side_exact(h, p));
    r = it->second;
  }
  memo_[v] = static_cast<uint32_t>(tag << 2) | static_cast<uint32_t>(r + 1);
  return r;
}

// The sides that follow from the triangle's vertices and the planes naming each vertex;
// 2 where the filter or exact arithmetic must decide (then `pending`).
int FragmentOps::known_sides(int32_t h, const Frag& f, std::vector<int>& s, bool& pending) const {
  int ts[3];
  for (int k = 0; k < 3; ++k) ts[k] = side(h, f.tri, k);
  pending = false;
  if (f.whole) {
    s.assign(ts, ts + 3);
    return 3;
  }
  const int n = static_cast<int>(f.poly.size());
  s.resize(n);
  const bool pos = ts[0] > 0 || ts[1] > 0 || ts[2] > 0, neg = ts[0] < 0 || ts[1] < 0 || ts[2] < 0;
  if (!(pos && neg)) {
    for (int k = 0; k < n; ++k) s[k] = pos ? 1 : (neg ? -1 : 0);
    return n;
  }
  for (int k = 0; k < n; ++k) {
    const FVert& v = f.poly[k];
    int r = 2;  // 2: not decided yet
    if (v.at >= 0) {
      r = ts[v.at];
    } else if (v.edge >= 0) {
      // Strictly inside edge (e, e+1): the sign follows from the endpoints' unless they are
      // strictly on opposite sides.
      const int sa = ts[v.edge], sb = ts[(v.edge + 1) % 3];
      if (sa == sb) r = sa;
      else if (sa == 0) r = sb;
      else if (sb == 0) r = sa;
      else if (v.pa == h) r = 0;
    } else if (v.pa == h || v.pb == h) {
      r = 0;
    }
    s[k] = r;
    pending |= r == 2;
  }
  return n;
}

int FragmentOps::classify(int32_t h, const Frag& f, std::vector<int>& s) const {
  bool pending;
  const int n = known_sides(h, f, s, pending);
  if (!pending) return n;
  {
    RoundUp up;
    for (int k = 0; k < n; ++k)
      if (s[k] == 2) ++filtered_, s[k] = planes_.filtered_side(h, f.poly[k].box);
  }
  const BspTriangle& t = tris_[f.tri];
  for (int k = 0; k < n; ++k) {
    if (s[k] != 2) continue;
    ++exact_;
    const FVert& v = f.poly[k];
    s[k] = v.edge >= 0 ? planes_.exact_side_edge(t.p[v.edge], t.p[(v.edge + 1) % 3], v.pa, h)
                       : planes_.exact_side_meet(f.tri, v.pa, v.pb, h);
  }
  return n;
}

Side FragmentOps::approx_side(int32_t h, const Frag& f, std::vector<int>& s) const {
  bool pending;
  const int n = known_sides(h, f, s, pending);
  if (!pending) return side_of(s.data(), n);
  bool pos = false, neg = false;
  int unknown = 0;
  for (int k = 0; k < n; ++k) {
    int r = s[k];
    if (r == 2) {
      const IBox& b = f.poly[k].box;
      r = planes_.approx_side(h, {0.5 * (b.x.inf() + b.x.sup()), 0.5 * (b.y.inf() + b.y.sup()),
                                  0.5 * (b.z.inf() + b.z.sup())});
    }
    if (r == 2) ++unknown;
    else pos |= r > 0, neg |= r < 0;
  }
  // Vertices too close to call count as a split when they could make one.
  if (unknown >= 2 || (unknown == 1 && (pos || neg))) return kSplit;
  return pos && neg ? kSplit : pos ? kFront : neg ? kBack : kCoplanar;
}

void FragmentOps::approx_points(const Frag& f, std::vector<Vec3>& out) const {
  const BspTriangle& t = tris_[f.tri];
  if (f.whole) {
    out.insert(out.end(), t.p, t.p + 3);
    return;
  }
  for (const FVert& v : f.poly) {
    const IBox& b = v.box;
    out.push_back(v.at >= 0 ? t.p[v.at]
                            : Vec3{0.5 * (b.x.inf() + b.x.sup()), 0.5 * (b.y.inf() + b.y.sup()),
                                   0.5 * (b.z.inf() + b.z.sup())});
  }
}

Side FragmentOps::guess_side(int32_t h, const Frag& f, const Vec3* pts, std::vector<int>& s) const {
  if (h == f.tri) return kCoplanar;  // its own plane
  const int n = f.whole ? 3 : static_cast<int>(f.poly.size());
  const Vec3* q = planes_.points(h);
  bool pos = false, neg = false;
  for (int i = 0; i < n; ++i) {
    const Vec3 p = pts[i];
    int r = planes_.approx_side(h, p);
    // Too close to call: a vertex of the triangle by its exact (memoized) side, a point
    // named by h, or inside an edge whose ends decide, as known_sides; else the fragment
    // by approx_side.
    if (r == 2) {
      if (f.whole || f.poly[i].at >= 0) {
        r = p == q[0] || p == q[1] || p == q[2] ? 0 : side(h, f.tri, f.whole ? i : f.poly[i].at);
      } else if (f.poly[i].pa == h || f.poly[i].pb == h) {
        r = 0;
      } else if (f.poly[i].edge >= 0) {
        const int e = f.poly[i].edge;
        const int sa = side(h, f.tri, e), sb = side(h, f.tri, (e + 1) % 3);
        r = sa == sb ? sa : sa == 0 ? sb : sb == 0 ? sa : 2;
      }
      if (r == 2) return approx_side(h, f, s);
    }
    pos |= r > 0, neg |= r < 0;
  }
  return pos && neg ? kSplit : pos ? kFront : neg ? kBack : kCoplanar;
}

Side FragmentOps::side_of(const int* s, int n) {
  bool pos = false, neg = false;
  for (int k = 0; k < n; ++k) pos |= s[k] > 0, neg |= s[k] < 0;
  return pos && neg ? kSplit : pos ? kFront : neg ? kBack : kCoplanar;
}

std::vector<FVert> FragmentOps::whole_poly() {
  std::vector<FVert> poly(3);
  for (int k = 0; k < 3; ++k) {
    poly[k].at = static_cast<int8_t>(k);
    poly[k].out = edge_label(k);
  }
  return poly;
}

FVert FragmentOps::crossing(int32_t tri, int32_t label, int32_t h) const {
  FVert q;
  if (label < 0) {
    // On a triangle edge: its endpoints are strictly on opposite sides of h (the fragment's
    // edge, part of it, crosses h strictly).
    const int k = -1 - label;
    const BspTriangle& t = tris_[tri];
    q.edge = static_cast<int8_t>(k);
    q.pa = h;
    q.box = planes_.edge_point(t.p[k], t.p[(k + 1) % 3], h);
  } else {
    // On the line where the triangle's plane meets plane `label`, which h crosses.
    q.pa = label;
    q.pb = h;
    q.box = planes_.meet_point(tri, label, h);
  }
  return q;
}

void FragmentOps::split(int32_t h, const Frag& f, const int* s, int n, Frag& front, Frag& back) const {
  const std::vector<FVert> poly = f.whole ? whole_poly() : f.poly;
  front = Frag{f.tri, false, {}};
  back = Frag{f.tri, false, {}};
  front.poly.reserve(n + 1);
  back.poly.reserve(n + 1);
  RoundUp up;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const FVert& v = poly[i];
    // A kept vertex's edge goes on along its old line unless the next part of the boundary
    // is cut away: then the edge runs in h to where the boundary comes back.
    if (s[i] >= 0) {
      front.poly.push_back(v);
      front.poly.back().out = s[j] >= 0 || s[i] > 0 ? v.out : h;
    }
    if (s[i] <= 0) {
      back.poly.push_back(v);
      back.poly.back().out = s[j] <= 0 || s[i] < 0 ? v.out : h;
    }
    if (s[i] * s[j] < 0) {
      FVert q = crossing(f.tri, v.out, h);
      q.out = s[i] > 0 ? h : v.out;
      front.poly.push_back(q);
      q.out = s[i] < 0 ? h : v.out;
      back.poly.push_back(q);
    }
  }
}

std::vector<P3> FragmentOps::exact_polygon(const Frag& f) const {
  const BspTriangle& t = tris_[f.tri];
  std::vector<P3> out;
  if (f.whole) {
    for (const Vec3& p : t.p) out.push_back(ep(p));
    return out;
  }
  for (const FVert& v : f.poly) {
    if (v.at >= 0) {
      out.push_back(ep(t.p[v.at]));
    } else if (v.edge >= 0) {
      const Vec3* h = planes_.points(v.pa);
      const K::Vector_3 n = normal(h);
      const P3 p = ep(t.p[v.edge]), q = ep(t.p[(v.edge + 1) % 3]);
      const K::FT dp = n * (p - ep(h[0])), dq = n * (q - ep(h[0]));
      out.push_back(p + (q - p) * (dp / (dp - dq)));
    } else {
      // y = x - o solves n_t.y = 0, n_i.y = ri, n_j.y = rj (o a point of plane t).
      const Vec3* pt = planes_.points(f.tri);
      const Vec3* pi = planes_.points(v.pa);
      const Vec3* pj = planes_.points(v.pb);
      const K::Vector_3 nt = normal(pt), ni = normal(pi), nj = normal(pj);
      const P3 o = ep(pt[0]);
      const K::FT ri = ni * (ep(pi[0]) - o), rj = nj * (ep(pj[0]) - o);
      const K::FT det = nt * CGAL::cross_product(ni, nj);
      out.push_back(o + (CGAL::cross_product(nj, nt) * ri + CGAL::cross_product(nt, ni) * rj) / det);
    }
  }
  return out;
}

}  // namespace vob::xmpvo::bsp
