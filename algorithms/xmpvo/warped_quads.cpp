#include "algorithms/xmpvo/warped_quads.h"

#include "harness/geometry/predicates.h"

namespace vob::xmpvo {

namespace {
bool warped(const ExteriorFaces& e, size_t i) {
  const Vec3* c = &e.corners[4 * i];
  return e.size[i] == 4 && orient3d(c[0], c[1], c[2], c[3]) != 0;
}
}  // namespace

size_t split_warped_quads(const ExteriorFaces& in, ExteriorFaces& out) {
  const size_t b = in.face.size();
  size_t warps = 0;
  for (size_t i = 0; i < b; ++i) warps += warped(in, i);
  if (warps == 0) return 0;
  out = ExteriorFaces{};
  out.points = in.points;
  const size_t n = b + warps;
  out.face.reserve(n);
  out.size.reserve(n);
  out.cell.reserve(n);
  out.vertex.reserve(4 * n);
  out.corners.reserve(4 * n);
  const auto add = [&](size_t i, int k0, int k1, int k2, int size) {
    out.face.push_back(in.face[i]);
    out.size.push_back(static_cast<int8_t>(size));
    out.cell.push_back(in.cell[i]);
    const int ks[4] = {k0, k1, k2, size == 4 ? 3 : -1};
    for (int k : ks) {
      out.vertex.push_back(k < 0 ? -1 : in.vertex[4 * i + k]);
      out.corners.push_back(k < 0 ? Vec3{} : in.corners[4 * i + k]);
    }
  };
  for (size_t i = 0; i < b; ++i) {
    if (!warped(in, i)) {
      add(i, 0, 1, 2, in.size[i]);
    } else {  // the loop's orientation kept: both normals still point out of the mesh
      add(i, 0, 1, 2, 3);
      add(i, 0, 2, 3, 3);
    }
  }
  return warps;
}

}  // namespace vob::xmpvo
