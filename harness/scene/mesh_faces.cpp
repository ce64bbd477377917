#include "harness/scene/mesh_faces.h"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "harness/geometry/polygon_plane.h"
#include "harness/scene/input_error.h"

namespace vob {

size_t MeshFaces::bytes() const {
  return (offsets.capacity() + verts.capacity() + cell0.capacity() + cell1.capacity() +
          cell_face_offsets.capacity() + cell_faces.capacity() + boundary.capacity()) *
         sizeof(int32_t);
}

namespace {
struct FaceKey {
  std::array<int32_t, 4> v;  // sorted point ids, -1 padded for triangles
  bool operator==(const FaceKey& o) const { return v == o.v; }
};
struct FaceKeyHash {
  size_t operator()(const FaceKey& k) const {
    uint64_t h = 1469598103934665603ull;
    for (int32_t x : k.v) h = (h ^ static_cast<uint32_t>(x)) * 1099511628211ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};
// Cyclic orientation of a face's vertex loop relative to its sorted key: +1 or -1, so two
// cells sharing a face see it with opposite parity exactly when they lie on opposite sides.
int loop_parity(const int32_t* loop, int n) {
  // Rotate so the smallest id comes first, then compare the two neighbours.
  int m = 0;
  for (int i = 1; i < n; ++i)
    if (loop[i] < loop[m]) m = i;
  return loop[(m + 1) % n] < loop[(m + n - 1) % n] ? 1 : -1;
}
}  // namespace

MeshFaces build_mesh_faces(const CellMesh& mesh, const std::string& source) {
  MeshFaces out;
  const size_t nc = mesh.num_cells();
  out.cell_face_offsets.resize(nc + 1);
  out.cell_face_offsets[0] = 0;
  for (size_t c = 0; c < nc; ++c)
    out.cell_face_offsets[c + 1] = out.cell_face_offsets[c] + cell_local_faces(mesh.types[c]).count;
  out.cell_faces.resize(out.cell_face_offsets[nc]);
  std::unordered_map<FaceKey, int32_t, FaceKeyHash> index;
  index.reserve(out.cell_faces.size());
  std::vector<int8_t> parity;
  for (size_t c = 0; c < nc; ++c) {
    const LocalFaces& lf = cell_local_faces(mesh.types[c]);
    const int32_t* p = mesh.cell_points(c);
    for (int f = 0; f < lf.count; ++f) {
      int32_t loop[4];
      const int n = lf.size[f];
      for (int i = 0; i < n; ++i) loop[i] = p[lf.v[f][i]];
      FaceKey key{{-1, -1, -1, -1}};
      for (int i = 0; i < n; ++i) {  // insertion sort of 3 or 4 ids
        int j = i;
        for (; j > 0 && key.v[j - 1] > loop[i]; --j) key.v[j] = key.v[j - 1];
        key.v[j] = loop[i];
      }
      const int par = loop_parity(loop, n);
      auto [it, fresh] = index.try_emplace(key, static_cast<int32_t>(out.cell0.size()));
      const int32_t id = it->second;
      if (fresh) {
        out.verts.insert(out.verts.end(), loop, loop + n);
        out.offsets.push_back(static_cast<int32_t>(out.verts.size()));
        out.cell0.push_back(static_cast<int32_t>(c));
        out.cell1.push_back(-1);
        parity.push_back(static_cast<int8_t>(par));
      } else {
        const std::string face = "face (" + std::to_string(key.v[0]) + "," +
                                 std::to_string(key.v[1]) + "," + std::to_string(key.v[2]) +
                                 (n == 4 ? "," + std::to_string(key.v[3]) : std::string()) + ")";
        if (out.cell1[id] != -1)
          throw InputError(source, face,
                           "shared by more than two cells (" + std::to_string(out.cell0[id]) +
                               ", " + std::to_string(out.cell1[id]) + ", " + std::to_string(c) + ")");
        if (parity[id] == par)
          throw InputError(source, face,
                           "cells " + std::to_string(out.cell0[id]) + " and " +
                               std::to_string(c) + " lie on the same side of it (overlapping cells)");
        out.cell1[id] = static_cast<int32_t>(c);
      }
      out.cell_faces[out.cell_face_offsets[c] + f] = id;
    }
  }
  for (size_t f = 0; f < out.cell0.size(); ++f)
    if (out.cell1[f] < 0) out.boundary.push_back(static_cast<int32_t>(f));
  return out;
}

FacePlanes build_face_planes(const CellMesh& mesh, const MeshFaces& faces) {
  FacePlanes pl;
  const size_t nf = faces.num_faces();
  pl.normal.resize(nf);
  pl.offset.resize(nf);
  for (size_t f = 0; f < nf; ++f) {
    const int32_t* v = faces.face_points(f);
    const int n = faces.face_size(f);
    Vec3 pts[4];
    for (int i = 0; i < n; ++i) pts[i] = mesh.points[v[i]];
    const PolygonPlane plane = newell_plane(pts, n);
    pl.normal[f] = plane.normal;
    pl.offset[f] = -dot(plane.normal, plane.centroid);
  }
  return pl;
}

Centroids build_cell_centroids(const CellMesh& mesh) {
  Centroids c;
  c.points.resize(mesh.num_cells());
  for (size_t i = 0; i < mesh.num_cells(); ++i) c.points[i] = mesh.cell_centroid(i);
  return c;
}

Centroids build_face_centroids(const CellMesh& mesh, const MeshFaces& faces) {
  Centroids c;
  c.points.resize(faces.num_faces());
  for (size_t f = 0; f < faces.num_faces(); ++f) {
    Vec3 s;
    const int n = faces.face_size(f);
    for (int i = 0; i < n; ++i) s += mesh.points[faces.face_points(f)[i]];
    c.points[f] = s / n;
  }
  return c;
}

}  // namespace vob
