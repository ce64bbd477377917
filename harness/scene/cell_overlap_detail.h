// Internals of the exact cell-overlap test (cell_overlap.h) shared by its parts: the exact
// determinant sign, per-type face triangles and edges, and the cell pair test itself
// (cell_pair_test.cpp). Not an interface for other code.
#pragma once
#include <cstdint>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/cell_types.h"

namespace vob::overlap_detail {

// Exact sign of det(u1 - u0, v1 - v0, x - o): doubles with a forward error bound, exact
// arithmetic (CGAL::Mpzf) when the bound cannot call it.
int sign_det(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1, const Vec3& o,
             const Vec3& x);

// The face triangles and edges of a cell type, from its local faces (quads as (0,1,2),
// (0,2,3)); built once per type.
struct TypeShape {
  int ntri = 0, nedge = 0;
  int tri[12][3];
  int edge[12][2];
  explicit TypeShape(CellType t);
  void add_tri(int a, int b, int c) { tri[ntri][0] = a, tri[ntri][1] = b, tri[ntri][2] = c, ++ntri; }
  void add_edge(int a, int b);
};
const TypeShape& type_shape(CellType t);

}  // namespace vob::overlap_detail
