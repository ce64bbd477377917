#include "algorithms/stencil/snapped_signs.h"

#include "harness/raster/raster_rule.h"
#include "harness/raster/sample_frame.h"

namespace vob::stencil {

int64_t apply_snapped_signs(mpvo::MpvoCore& core, const Camera& view, std::vector<int64_t>& xy) {
  const SampleFrame frame(view, 1);
  const std::vector<Vec3>& pts = core.scene().mesh().points;
  constexpr int64_t kBehind = INT64_MIN;  // marks a point not in front of the eye
  xy.resize(2 * pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    double x, y, zc;
    const bool front = frame.project(pts[i], x, y, zc) && (!frame.ortho() || zc >= 0);
    xy[2 * i] = front ? gl_snap(x) : kBehind;
    xy[2 * i + 1] = front ? gl_snap(y) : 0;
  }
  const MeshFaces& mf = core.faces();
  int64_t flipped = 0;
  for (size_t f = 0; f < mf.num_faces(); ++f) {
    const int n = mf.face_size(f);
    const int32_t* id = mf.face_points(f);
    __int128 area = 0;  // twice the signed area (shoelace), exact
    bool ok = true;
    for (int i = 0; i < n && ok; ++i) {
      const int64_t* a = &xy[2 * size_t(id[i])];
      const int64_t* b = &xy[2 * size_t(id[(i + 1) % n])];
      ok = a[0] != kBehind && b[0] != kBehind;
      area += __int128(a[0]) * b[1] - __int128(b[0]) * a[1];
    }
    if (!ok || area == 0) continue;
    const int s = area > 0 ? 1 : -1;
    if (s != core.face_sign(int32_t(f))) {
      core.set_face_sign(int32_t(f), s);
      ++flipped;
    }
  }
  return flipped;
}

}  // namespace vob::stencil
