#include "harness/scene/mesh_faces.h"

#include <algorithm>
#include <array>

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
// Local face f of cell c as its vertex loop; returns its size.
int face_loop(const CellMesh& mesh, size_t c, int f, int32_t* loop) {
  const LocalFaces& lf = cell_local_faces(mesh.types[c]);
  const int32_t* p = mesh.cell_points(c);
  const int n = lf.size[f];
  for (int i = 0; i < n; ++i) loop[i] = p[lf.v[f][i]];
  return n;
}
FaceKey sorted_key(const int32_t* loop, int n) {
  FaceKey key{{-1, -1, -1, -1}};
  for (int i = 0; i < n; ++i) {  // insertion sort of 3 or 4 ids
    int j = i;
    for (; j > 0 && key.v[j - 1] > loop[i]; --j) key.v[j] = key.v[j - 1];
    key.v[j] = loop[i];
  }
  return key;
}
}  // namespace

MeshFaces build_mesh_faces(const CellMesh& mesh, const std::string& source) {
  MeshFaces out;
  const size_t nc = mesh.num_cells();
  out.cell_face_offsets.resize(nc + 1);
  out.cell_face_offsets[0] = 0;
  for (size_t c = 0; c < nc; ++c)
    out.cell_face_offsets[c + 1] = out.cell_face_offsets[c] + cell_local_faces(mesh.types[c]).count;
  const size_t slots = static_cast<size_t>(out.cell_face_offsets[nc]);
  out.cell_faces.resize(slots);
  // Every cell's local faces (slots) by their sorted point ids. Equal keys are found by
  // grouping the slots by smallest point id (a counting sort) and sorting each small group,
  // not by a hash map, whose node per face went to allocation and misses (0.9-1.0 s on a
  // 1M-cell helix, 2.1 s on a 1.32M-cell gmsh mesh; now 0.24 and 0.62 s).
  std::vector<FaceKey> key(slots);
  const int64_t np = static_cast<int64_t>(mesh.num_points());
  for (size_t c = 0; c < nc; ++c)
    for (int f = 0, count = cell_local_faces(mesh.types[c]).count; f < count; ++f) {
      int32_t loop[4];
      const int n = face_loop(mesh, c, f, loop);
      const FaceKey k = sorted_key(loop, n);
      key[out.cell_face_offsets[c] + f] = k;
      if (k.v[0] < 0 || k.v[n - 1] >= np)  // validate_cell_mesh refuses these first
        throw InputError(source, "cell " + std::to_string(c), "point id out of range");
    }
  std::vector<int32_t> group(static_cast<size_t>(np) + 1, 0);  // by smallest id
  for (size_t s = 0; s < slots; ++s) ++group[key[s].v[0] + 1];
  for (size_t i = 1; i < group.size(); ++i) group[i] += group[i - 1];
  std::vector<int32_t> by_min(slots);
  {
    std::vector<int32_t> cursor(group.begin(), group.end() - 1);
    for (size_t s = 0; s < slots; ++s) by_min[cursor[key[s].v[0]]++] = static_cast<int32_t>(s);
  }
  // first[s]: the lowest slot with s's key (s itself for a face's first appearance).
  // Within a group the smallest ids are equal: keys differ in their other three.
  const auto same = [&](int32_t x, int32_t y) {
    const auto &a = key[x].v, &b = key[y].v;
    return a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
  };
  const auto before = [&](int32_t x, int32_t y) {
    const auto &a = key[x].v, &b = key[y].v;
    if (a[1] != b[1]) return a[1] < b[1];
    if (a[2] != b[2]) return a[2] < b[2];
    if (a[3] != b[3]) return a[3] < b[3];
    return x < y;
  };
  std::vector<int32_t> first(slots);
  for (size_t g = 0; g + 1 < group.size(); ++g) {
    int32_t* b = by_min.data() + group[g];
    int32_t* e = by_min.data() + group[g + 1];
    std::sort(b, e, before);
    for (int32_t* i = b; i < e; ++i) first[*i] = i > b && same(i[-1], *i) ? first[i[-1]] : *i;
  }
  // Faces numbered in order of first appearance (cell by cell, local faces in order); a
  // later appearance is the face's second cell.
  std::vector<int8_t> parity;
  for (size_t c = 0; c < nc; ++c)
    for (int f = 0, count = cell_local_faces(mesh.types[c]).count; f < count; ++f) {
      const size_t s = static_cast<size_t>(out.cell_face_offsets[c] + f);
      int32_t loop[4];
      const int n = face_loop(mesh, c, f, loop);
      const int par = loop_parity(loop, n);
      if (first[s] == static_cast<int32_t>(s)) {
        out.cell_faces[s] = static_cast<int32_t>(out.cell0.size());
        out.verts.insert(out.verts.end(), loop, loop + n);
        out.offsets.push_back(static_cast<int32_t>(out.verts.size()));
        out.cell0.push_back(static_cast<int32_t>(c));
        out.cell1.push_back(-1);
        parity.push_back(static_cast<int8_t>(par));
        continue;
      }
      const int32_t id = out.cell_faces[first[s]];
      const auto face = [&] {  // named only in an error
        const FaceKey& k = key[s];
        return "face (" + std::to_string(k.v[0]) + "," + std::to_string(k.v[1]) + "," + std::to_string(k.v[2]) +
               (n == 4 ? "," + std::to_string(k.v[3]) : std::string()) + ")";
      };
      if (out.cell1[id] != -1)
        throw InputError(source, face(),
                         "shared by more than two cells (" + std::to_string(out.cell0[id]) + ", " +
                             std::to_string(out.cell1[id]) + ", " + std::to_string(c) + ")");
      if (parity[id] == par)
        throw InputError(source, face(),
                         "cells " + std::to_string(out.cell0[id]) + " and " + std::to_string(c) +
                             " lie on the same side of it (overlapping cells)");
      out.cell1[id] = static_cast<int32_t>(c);
      out.cell_faces[s] = id;
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
