#include "algorithms/xmpvo/plane_keys.h"

namespace vob::xmpvo {

PlaneKey plane_key(const VertexRay& r, const FacePlane& f) {
  // The same operations, in the same order, as vertex_plane_order's bound.
  const Fd w{r.w[0], r.w[1]};
  Fd num, den;
  for (int i = 0; i < 3; ++i) {
    const Fd n{f.n[i][0], f.n[i][1]}, h{r.h[i][0], r.h[i][1]};
    if (r.g.ortho) {
      num = num + n * (Fd{f.f[0][i], 0} * w - h);
      den = den + n * Fd{r.g.dir[i], 0};
    } else {
      num = num + n * (Fd{f.f[0][i], 0} - Fd{r.g.eye[i], 0});
      den = den + n * (h - w * Fd{r.g.eye[i], 0});
    }
  }
  if (r.g.ortho) den = den * w;
  else num = num * w;
  return {num, den, fd_sign(den)};
}

}  // namespace vob::xmpvo
