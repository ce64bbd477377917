// CellMesh: an unstructured mesh of zoo cells in CSR form, plus one scalar per point.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"
#include "harness/scene/cell_types.h"

namespace vob {

struct CellMesh {
  std::vector<Vec3> points;
  std::vector<double> scalars;     // one per point; empty means all zero
  std::vector<CellType> types;     // one per cell
  std::vector<int32_t> offsets{0};  // size cells+1, into conn
  std::vector<int32_t> conn;       // point ids, VTK vertex order

  size_t num_cells() const { return types.size(); }
  size_t num_points() const { return points.size(); }
  const int32_t* cell_points(size_t c) const { return conn.data() + offsets[c]; }
  int cell_size(size_t c) const { return offsets[c + 1] - offsets[c]; }
  void add_cell(CellType t, std::initializer_list<int32_t> ids);
  void add_cell(CellType t, const int32_t* ids);
  double scalar(size_t point) const { return scalars.empty() ? 0.0 : scalars[point]; }
  Vec3 cell_centroid(size_t c) const;  // mean of the cell's vertices
  double cell_scalar(size_t c) const;  // mean of the cell's point scalars
  Aabb bounds() const;
  size_t bytes() const;
};

// Checks what DESIGN.md asks of every loaded mesh: finite coordinates and scalars, indices
// in range, supported types, positively oriented, non-degenerate convex cells (every cell
// vertex strictly inside every face plane, decided with exact predicates). Throws InputError
// naming `source`, the element and the reason. Face sharing is checked when faces are built.
void validate_cell_mesh(const CellMesh& mesh, const std::string& source);

}  // namespace vob
