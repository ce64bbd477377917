// The exterior (boundary) faces of a cell mesh, the list XMPVO, SXMPVO and stencil-XMPVO
// all start from. Each face keeps the loop seen from its one cell, so its right-hand
// normal points out of the mesh. Points are kept twice on purpose: compact ids for
// per-point work done once per view, and per-face records for visiting faces in any order
// without gathering.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/mesh_faces.h"

namespace vob {

struct ExteriorFaces {
  std::vector<int32_t> face;    // unique face ids (MeshFaces::boundary order)
  std::vector<int8_t> size;     // 3 or 4 vertices
  std::vector<int32_t> cell;    // the owning cell
  std::vector<int32_t> vertex;  // 4 per face: index into `points`, -1 past `size`
  std::vector<Vec3> points;     // the points of exterior faces, each once
  std::vector<Vec3> corners;    // 4 per face: its points in loop order (zero past `size`)
  size_t bytes() const;
};

ExteriorFaces build_exterior_faces(const CellMesh& mesh, const MeshFaces& faces);

}  // namespace vob
