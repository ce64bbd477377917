#include "algorithms/xmpvo/plane_keys.h"

namespace vob::xmpvo {

ViewPlane ViewPlane::of(const ViewGeometry& g, const FacePlane& f) {
  ViewPlane vp;
  for (int i = 0; i < 3; ++i) {
    const Fd n{f.n[i][0], f.n[i][1]};
    if (g.ortho) {
      vp.a = vp.a + n * Fd{f.f[0][i], 0};
      vp.b = vp.b + n * Fd{g.dir[i], 0};
    } else {
      vp.a = vp.a + n * (Fd{f.f[0][i], 0} - Fd{g.eye[i], 0});
    }
  }
  return vp;
}

RayTerms RayTerms::of(const VertexRay& r) {
  RayTerms t;
  t.w = {r.w[0], r.w[1]};
  for (int i = 0; i < 3; ++i) {
    const Fd h{r.h[i][0], r.h[i][1]};
    t.q[i] = r.g.ortho ? h : h - t.w * Fd{r.g.eye[i], 0};
  }
  return t;
}

// Perspective: num = w n.(f0 - eye), den = n.(h - w eye). Orthographic: num = w n.f0 - n.h,
// den = w n.dir.
PlaneKey plane_key(const ViewGeometry& g, const RayTerms& r, const FacePlane& f, const ViewPlane& vp) {
  Fd dot;
  for (int i = 0; i < 3; ++i) dot = dot + Fd{f.n[i][0], f.n[i][1]} * r.q[i];
  PlaneKey k;
  if (g.ortho) {
    k.num = r.w * vp.a - dot;
    k.den = r.w * vp.b;
  } else {
    k.num = r.w * vp.a;
    k.den = dot;
  }
  k.den_sign = fd_sign(k.den);
  return k;
}

}  // namespace vob::xmpvo
