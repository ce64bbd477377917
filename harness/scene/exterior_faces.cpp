#include "harness/scene/exterior_faces.h"

namespace vob {

size_t ExteriorFaces::bytes() const {
  return face.capacity() * 4 + size.capacity() + cell.capacity() * 4 + vertex.capacity() * 4 +
         (points.capacity() + corners.capacity()) * sizeof(Vec3);
}

ExteriorFaces build_exterior_faces(const CellMesh& mesh, const MeshFaces& faces) {
  ExteriorFaces e;
  e.face = faces.boundary;
  const size_t b = e.face.size();
  e.size.resize(b);
  e.cell.resize(b);
  e.vertex.assign(4 * b, -1);
  e.corners.assign(4 * b, Vec3{});
  std::vector<int32_t> compact(mesh.points.size(), -1);
  for (size_t i = 0; i < b; ++i) {
    const int32_t f = e.face[i];
    const int n = faces.face_size(f);
    for (int k = 0; k < n; ++k) {
      const int32_t pid = faces.face_points(f)[k];
      if (compact[pid] < 0) {
        compact[pid] = static_cast<int32_t>(e.points.size());
        e.points.push_back(mesh.points[pid]);
      }
      e.vertex[4 * i + k] = compact[pid];
      e.corners[4 * i + k] = mesh.points[pid];
    }
    e.size[i] = static_cast<int8_t>(n);
    e.cell[i] = faces.cell0[f];
  }
  return e;
}

}  // namespace vob
