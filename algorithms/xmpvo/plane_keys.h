// XMPVO's depth keys at one arrangement vertex: where the vertex's ray meets each face's
// plane, as a fraction num / den in doubles with a running rounding bound (the semi-static
// filter of bounded_double.h), computed once per face and query instead of once per
// comparison. Comparing two keys is then two products; a comparison too close to call
// returns 2 and the caller asks the exact vertex_plane_order.
#pragma once
#include <cmath>

#include "algorithms/xmpvo/bounded_double.h"
#include "algorithms/xmpvo/face_pairs.h"

namespace vob::xmpvo {

struct PlaneKey {
  Fd num, den;
  int den_sign;  // fd_sign(den)
};

// The vertex-independent part of a face plane's key at one view, n . (f0 - eye)
// (perspective) or n . f0 (orthographic), beside the plane's normal n: a key then reads one
// cache line per face, not the face plane's two and this table's.
struct alignas(64) ViewPlane {
  double n[3][2];  // FacePlane::n
  Fd a;
  static ViewPlane of(const ViewGeometry& g, const FacePlane& f);
};

// The vertex's part: h - w eye (perspective) or h (orthographic), and w.
struct RayTerms {
  Fd w, q[3];
  static RayTerms of(const VertexRay& r);
};

// The ray parameter of face plane f on the vertex's ray (the terms of vertex_plane_order,
// regrouped: the bound is of the same exact value). Perspective: num = w n.(f0 - eye),
// den = n.(h - w eye). Orthographic: num = w n.f0 - n.h, den = w n.dir.
inline PlaneKey plane_key(const ViewGeometry& g, const RayTerms& r, const ViewPlane& vp) {
  Fd dot;
  for (int i = 0; i < 3; ++i) dot = dot + Fd{vp.n[i][0], vp.n[i][1]} * r.q[i];
  PlaneKey k;
  if (g.ortho) {
    Fd b;
    for (int i = 0; i < 3; ++i) b = b + Fd{vp.n[i][0], vp.n[i][1]} * Fd{g.dir[i], 0};
    k.num = r.w * vp.a - dot;
    k.den = r.w * b;
  } else {
    k.num = r.w * vp.a;
    k.den = dot;
  }
  k.den_sign = fd_sign(k.den);
  return k;
}

// -1 when a's plane is met first, +1 b's; 2 when the filter cannot tell (then the exact
// vertex_plane_order decides, 0 included).
inline int compare_keys(const PlaneKey& a, const PlaneKey& b) {
  if (a.den_sign == 2 || b.den_sign == 2) return 2;
  const int s = fd_sign(a.num * b.den - b.num * a.den);
  return s == 2 ? 2 : s * a.den_sign * b.den_sign;
}

}  // namespace vob::xmpvo
