// Internals of the exact cell-overlap test (cell_overlap.h) shared by its parts: the exact
// determinant sign, per-type face triangles and edges, and the cell pair test itself
// (cell_pair_test.cpp). Not an interface for other code.
#pragma once
#include <cstdint>
#include <vector>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/cell_overlap.h"
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

// Bit f set when local face f of cell c is a quad that is not exactly planar (exact
// orientation of its four points); has_non_planar_quad: any bit.
uint8_t non_planar_quads(const CellMesh& mesh, int32_t c);
bool has_non_planar_quad(const CellMesh& mesh, int32_t c);
// cells_interpenetrate with both cells' non_planar_quads known.
bool cells_interpenetrate(const CellMesh& mesh, int32_t a, int32_t b, uint8_t quads_a, uint8_t quads_b);

// The oracle's polyhedron of a cell (cell_planes.h), approximately: vertices in doubles
// relative to `ref` (the cell's first point), each within `err` (per coordinate) of a
// point where three face planes meet; a superset of the true vertices
// (cell_model_overlap.cpp says how). `box` holds the cell's points and the polyhedron.
struct ModelCell {
  Vec3 ref;
  std::vector<Vec3> v;
  double err = 0;
  Aabb box;
  bool bounded = true;   // false: no extent bound found (the polyhedron may be unbounded)
  bool reliable = true;  // v holds every vertex (bounded, no triple left undecided, >= 4)
};
ModelCell model_cell(const CellMesh& mesh, int32_t c);

// The pair test of the oracle's model: a filter on the models' vertices (when both are
// reliable) that proves most pairs overlap by at most tol / 4, else the exact LP.
ModelOverlap model_overlap(const CellMesh& mesh, int32_t a, int32_t b, const ModelCell* ma,
                           const ModelCell* mb, double tol);

}  // namespace vob::overlap_detail
