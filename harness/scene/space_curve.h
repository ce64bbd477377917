// Renumbering a cell mesh along a space-filling curve. Meshers number cells in the order
// they made them, not in space order, so neighbours across a face can lie megabytes apart
// and every step of an adjacency walk (the MPVO DFS) is a cache miss. Cells sorted by the
// Morton code of their centroids, and points numbered by first use in that cell order, put
// neighbours close together in memory; the face structures built from the renumbered mesh
// then follow the cells. The numbering is view-independent: it is done once, in prepare.
#pragma once
#include <cstdint>
#include <vector>

#include "harness/scene/cell_mesh.h"

namespace vob {

// A mesh renumbered from an input mesh: cell c of `mesh` is input cell input_cell[c],
// point p of `mesh` is input point input_point[p]. Cell types, vertex order (hence
// orientation) and scalars are unchanged.
struct RenumberedMesh {
  CellMesh mesh;
  std::vector<int32_t> input_cell;   // new cell id -> input cell id
  std::vector<int32_t> input_point;  // new point id -> input point id
  size_t bytes() const;
};

// Codes along a curve through the 2^21 cubed grid of `box` (p quantized per axis; a flat
// axis maps to 0): Morton (Z order: bits interleaved, long jumps between octants) and
// Hilbert (consecutive codes are face-adjacent grid cells).
uint64_t morton_code(Vec3 p, const Aabb& box);
uint64_t hilbert_code(Vec3 p, const Aabb& box);
enum class Curve { Morton, Hilbert };

// The cells in increasing code of their centroids (ties by input id): the new cell order,
// new id -> input id. A permutation of [0, cells).
std::vector<int32_t> curve_cell_order(const CellMesh& mesh, Curve curve);

// `mesh` with its cells in `cell_order` (new id -> input id, a permutation) and its points
// numbered by first use in that order; points no cell uses follow in input order.
RenumberedMesh permute_cells(const CellMesh& mesh, const std::vector<int32_t>& cell_order);

// `mesh` with cells in `cell_order` and points renumbered by `point_order` (both new id ->
// input id, permutations): the generators' shuffle.
CellMesh permute_mesh(const CellMesh& mesh, const std::vector<int32_t>& cell_order,
                      const std::vector<int32_t>& point_order);

// How far apart in memory a numbering puts cells that share a point, as an estimate of the
// cache misses of an adjacency walk: cells are taken in `cell_order` (new id -> input id;
// empty: the input's own order) and, for every point a cell shares with an earlier cell,
// the distance in new ids to the last earlier cell that used it is a "far reuse" when it
// exceeds `near` cells. Returns far reuses / all reuses, in [0, 1]; 0 for a mesh with none.
// With k cells sharing a point, a random numbering puts its users about n / k apart, so on
// meshes small enough for the cache (n / k below `near`) the fraction stays low either way.
// O(connectivity), view-independent: the MPVO family's prepare compares the input's
// numbering with the curve's by it and keeps the input's when the curve is not better.
// kNearCells: cells whose DFS arrays (about 30 bytes a cell) fit in a 1 MB L2 cache.
inline constexpr int32_t kNearCells = 8192;
double far_reuse_fraction(const CellMesh& mesh, const std::vector<int32_t>& cell_order,
                          int32_t near = kNearCells);

// permute_cells(mesh, curve_cell_order(mesh, curve)).
RenumberedMesh renumber_along_curve(const CellMesh& mesh, Curve curve = Curve::Hilbert);

}  // namespace vob
