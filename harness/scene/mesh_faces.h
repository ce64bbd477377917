// Derived structures of a CellMesh, each built only when an algorithm asks for it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/scene/cell_mesh.h"

namespace vob {

// Unique faces with the one or two cells that own them. A face's vertex list is the one
// seen from cell0, so its right-hand normal points out of cell0 (into cell1 when shared).
struct MeshFaces {
  std::vector<int32_t> offsets{0};  // size faces+1
  std::vector<int32_t> verts;       // point ids
  std::vector<int32_t> cell0;
  std::vector<int32_t> cell1;       // -1 on the boundary
  // Per cell, the unique face id of each local face, in the cell type's local order.
  std::vector<int32_t> cell_face_offsets;  // size cells+1
  std::vector<int32_t> cell_faces;
  std::vector<int32_t> boundary;    // ids of faces with cell1 == -1

  size_t num_faces() const { return cell0.size(); }
  int face_size(size_t f) const { return offsets[f + 1] - offsets[f]; }
  const int32_t* face_points(size_t f) const { return verts.data() + offsets[f]; }
  // The neighbour of `cell` across face f, or -1.
  int32_t other(size_t f, int32_t cell) const { return cell0[f] == cell ? cell1[f] : cell0[f]; }
  size_t bytes() const;
};

// Builds the unique faces. Throws InputError (naming `source`) for a face shared by more
// than two cells, or shared by two cells that lie on the same side of it (overlap).
MeshFaces build_mesh_faces(const CellMesh& mesh, const std::string& source);

// Plane of each unique face: n.x + d = 0 with n pointing out of cell0 (Newell normal for
// quads, not normalised: its length is twice the face area).
struct FacePlanes {
  std::vector<Vec3> normal;
  std::vector<double> offset;
  size_t bytes() const { return normal.capacity() * sizeof(Vec3) + offset.capacity() * sizeof(double); }
};
FacePlanes build_face_planes(const CellMesh& mesh, const MeshFaces& faces);

struct Centroids {
  std::vector<Vec3> points;
  size_t bytes() const { return points.capacity() * sizeof(Vec3); }
};
Centroids build_cell_centroids(const CellMesh& mesh);
Centroids build_face_centroids(const CellMesh& mesh, const MeshFaces& faces);

}  // namespace vob
