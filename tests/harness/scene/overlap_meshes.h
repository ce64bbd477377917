// Meshes for the interpenetration tests: pairs of tetrahedra in every touching
// configuration, blocks side by side (shared or duplicated nodes, conforming or not) and
// blocks that interpenetrate.
#pragma once
#include <vector>

#include "harness/scene/cell_mesh.h"
#include "tests/harness/oracle/test_meshes.h"

namespace vob::test {

inline CellMesh translated(CellMesh m, Vec3 by) {
  for (Vec3& p : m.points) p += by;
  return m;
}

// `a` then `b`, b's points duplicated (its point and cell ids shifted).
inline CellMesh appended(const CellMesh& a, const CellMesh& b) {
  CellMesh m = a;
  const int32_t base = int32_t(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  if (!a.scalars.empty() || !b.scalars.empty()) {
    m.scalars.resize(a.points.size(), 0.0);
    for (size_t i = 0; i < b.points.size(); ++i) m.scalars.push_back(b.scalar(i));
  }
  for (size_t c = 0; c < b.num_cells(); ++c) {
    int32_t ids[8];
    for (int i = 0; i < b.cell_size(c); ++i) ids[i] = b.cell_points(c)[i] + base;
    m.add_cell(b.types[c], ids);
  }
  return m;
}

// One positively oriented tetrahedron per call, on its own (duplicated) points.
inline void add_tet(CellMesh& m, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (dot(cross(b - a, c - a), d - a) < 0) std::swap(b, c);
  const int32_t base = int32_t(m.points.size());
  for (const Vec3& p : {a, b, c, d}) m.points.push_back(p);
  m.add_cell(CellType::Tetra, {base, base + 1, base + 2, base + 3});
}

inline CellMesh tet_pair(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e, Vec3 f, Vec3 g, Vec3 h) {
  CellMesh m;
  add_tet(m, a, b, c, d);
  add_tet(m, e, f, g, h);
  return m;
}

// Two n^3 Kuhn blocks that interpenetrate: the second moved by (n/2 + 0.25, 0.3, 0.2) * h.
inline CellMesh interpenetrating_blocks(int n, double h = 1.0) {
  const CellMesh a = tet_block(n, h);
  return appended(a, translated(a, Vec3{(0.5 * n + 0.25) * h, 0.3 * h, 0.2 * h}));
}

}  // namespace vob::test
