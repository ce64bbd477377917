#include "harness/scene/cell_mesh.h"

#include <cmath>

#include "harness/geometry/predicates.h"
#include "harness/scene/coordinates.h"
#include "harness/scene/input_error.h"

namespace vob {

void CellMesh::add_cell(CellType t, std::initializer_list<int32_t> ids) {
  types.push_back(t);
  conn.insert(conn.end(), ids.begin(), ids.end());
  offsets.push_back(static_cast<int32_t>(conn.size()));
}

void CellMesh::add_cell(CellType t, const int32_t* ids) {
  types.push_back(t);
  conn.insert(conn.end(), ids, ids + cell_vertex_count(t));
  offsets.push_back(static_cast<int32_t>(conn.size()));
}

Vec3 CellMesh::cell_centroid(size_t c) const {
  Vec3 s;
  const int n = cell_size(c);
  const int32_t* p = cell_points(c);
  for (int i = 0; i < n; ++i) s += points[p[i]];
  return s / n;
}

double CellMesh::cell_scalar(size_t c) const {
  if (scalars.empty()) return 0.0;
  double s = 0;
  const int n = cell_size(c);
  const int32_t* p = cell_points(c);
  for (int i = 0; i < n; ++i) s += scalars[p[i]];
  return s / n;
}

Aabb CellMesh::bounds() const {
  Aabb b;
  for (const Vec3& p : points) b.add(p);
  return b;
}

size_t CellMesh::bytes() const {
  return points.capacity() * sizeof(Vec3) + scalars.capacity() * sizeof(double) +
         types.capacity() * sizeof(CellType) + offsets.capacity() * sizeof(int32_t) +
         conn.capacity() * sizeof(int32_t);
}

void validate_cell_mesh(const CellMesh& m, const std::string& source) {
  if (m.num_cells() == 0) throw InputError(source, "cells", "the mesh has no cells");
  check_coordinates(m.points, source);
  if (!m.scalars.empty() && m.scalars.size() != m.points.size())
    throw InputError(source, "scalars", "expected " + std::to_string(m.points.size()) +
                                            " point scalars, got " +
                                            std::to_string(m.scalars.size()));
  for (size_t i = 0; i < m.scalars.size(); ++i)
    if (!std::isfinite(m.scalars[i]))
      throw InputError(source, "point " + std::to_string(i), "scalar is not finite");
  if (m.offsets.size() != m.types.size() + 1)
    throw InputError(source, "cells", "offsets and types disagree in length");
  const auto np = static_cast<int64_t>(m.points.size());
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const std::string cell = "cell " + std::to_string(c);
    if (!is_supported_cell_code(static_cast<int>(m.types[c])))
      throw InputError(source, cell, "unsupported cell type " +
                                         std::to_string(static_cast<int>(m.types[c])));
    if (m.cell_size(c) != cell_vertex_count(m.types[c]))
      throw InputError(source, cell, std::string(cell_type_name(m.types[c])) + " needs " +
                                         std::to_string(cell_vertex_count(m.types[c])) +
                                         " points, has " + std::to_string(m.cell_size(c)));
    const int32_t* p = m.cell_points(c);
    const int n = m.cell_size(c);
    for (int i = 0; i < n; ++i) {
      if (p[i] < 0 || p[i] >= np)
        throw InputError(source, cell, "point index " + std::to_string(p[i]) + " out of range");
      for (int j = 0; j < i; ++j)
        if (p[i] == p[j])
          throw InputError(source, cell, "repeats point " + std::to_string(p[i]) +
                                             " (degenerate cell)");
    }
    // Convex and positively oriented: each vertex not on a face lies strictly inside it.
    // A quad is tested in both of its triangulations, (0,1,2)+(0,2,3) and (0,1,3)+(1,2,3):
    // a non-planar quad is drawn split one way or the other, and the cell must be convex
    // whichever way, or orderers and the oracle would disagree about its boundary.
    static constexpr int kTriangles[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}};
    const LocalFaces& lf = cell_local_faces(m.types[c]);
    for (int f = 0; f < lf.count; ++f) {
      const int ntri = lf.size[f] == 4 ? 4 : 1;
      for (int t = 0; t < ntri; ++t) {
        const int* tri = kTriangles[t];
        const Vec3 a = m.points[p[lf.v[f][tri[0]]]], b = m.points[p[lf.v[f][tri[1]]]],
                   cc = m.points[p[lf.v[f][tri[2]]]];
        for (int k = 0; k < n; ++k) {
          bool on_face = false;
          for (int q = 0; q < lf.size[f]; ++q) on_face |= (lf.v[f][q] == k);
          if (on_face) continue;
          const int s = orient3d(a, b, cc, m.points[p[k]]);
          if (s >= 0) {
            const std::string split =
                lf.size[f] == 4 ? std::string(" split ") + (t < 2 ? "0-2" : "1-3") : "";
            throw InputError(source, cell,
                             s == 0 ? "is degenerate (vertex " + std::to_string(k) +
                                          " lies on face " + std::to_string(f) + split + ")"
                                    : "is inverted or not convex (vertex " + std::to_string(k) +
                                          " outside face " + std::to_string(f) + split + ")");
          }
        }
      }
    }
  }
}

}  // namespace vob
