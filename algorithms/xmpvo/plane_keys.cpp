#include "algorithms/xmpvo/plane_keys.h"

namespace vob::xmpvo {

ViewPlane ViewPlane::of(const ViewGeometry& g, const FacePlane& f) {
  ViewPlane vp;
  for (int i = 0; i < 3; ++i) {
    vp.n[i][0] = f.n[i][0], vp.n[i][1] = f.n[i][1];
    const Fd n{f.n[i][0], f.n[i][1]};
    vp.a = vp.a + n * (g.ortho ? Fd{f.f[0][i], 0} : Fd{f.f[0][i], 0} - Fd{g.eye[i], 0});
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

}  // namespace vob::xmpvo
