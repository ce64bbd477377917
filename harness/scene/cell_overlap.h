// Interpenetrating cells: every pair of cells of a mesh whose interiors intersect, found
// exactly. Per-cell validation (cell_mesh.h) and face sharing (mesh_faces.h) cannot see two
// volumes meshed over the same space (parts of an assembly that intersect, a volume meshed
// twice): their cells share no face. Such a mesh has no visibility order at all.
//
// Candidates are the pairs whose bounding boxes overlap with positive volume (CGAL's
// box_self_intersection_d, half-open boxes: boxes that only touch cannot hide
// interpenetrating cells). Each candidate is then decided exactly: a cell is the convex hull
// of its vertices, and two convex polytopes have disjoint interiors iff some plane has one
// on each closed side; it suffices to try the planes of the hulls' facets and the planes
// spanned by an edge of one and an edge of the other (the facets of the Minkowski
// difference). Face triangles of non-planar quads are tried along both diagonals, and the
// diagonals count as edges, so the candidate set covers every hull whatever its
// triangulation. Signs are exact: a floating-point determinant with a forward error bound,
// exact arithmetic (CGAL::Mpzf) when the bound cannot decide. Touching cells (a shared
// face, edge or vertex, faces lying on each other with duplicated nodes) are separated by a
// plane through the contact and are not reported; a cell moved into another by any amount
// is. One exception to "cell = hull": two cells sharing a whole non-planar quad (same
// coordinates) would overlap in the sliver between its two triangulations; they count as
// neighbours when each lies strictly beyond the other's face triangles.
//
// That exhaustive search (find_overlapping_cells) is the reference. Its cost is the number
// of candidates: ~44 per cell on the helix (198M pairs for 4.5M cells), every one decided
// exactly, ~93-102 s of CPU on this machine (docs/design-notes.md).
//
// The default (check_overlapping_cells, `vobench validate`, `--validate full`) first runs
// certify_cells_disjoint, which decides WHETHER any pair interpenetrates from the boundary
// faces B (faces with one owner) and one point per face-connected component of cells:
//  (1) every boundary triangle t (owner e) against every cell a whose closed box meets t's:
//      the exact cell test decides (e, a) unless a is e or its face neighbour, or a plane
//      keeps t out of a's interior: a lies on the closed outer side of t's plane, or t on
//      the closed outer side of a face plane of a without lying in it;
//  (2) per face-connected component C, a point p strictly inside one of its cells c (checked
//      exactly) against every cell whose closed box contains p, decided by the exact test
//      (a cell whose closed hull holds p overlaps c).
// Why that is enough (planar faces; a non-planar quad leaves the answer to the exhaustive
// search): let w(x) be the number of cells whose interior holds x. Cells are convex,
// positively oriented and face neighbours see their face with opposite orientation, so off
// the faces w is the winding number of B, constant on each component of R^3 minus B.
// If (1) reports nothing, B misses every cell interior and every interior face's relative
// interior: t meeting the interior of a is never skipped (a point x of it is strictly
// inside every face plane of a, and a has vertices on both sides of t's plane), and e then
// overlaps a; t through the relative interior of an interior face F reaches the interior of
// one of F's cells; t lying on F in F's plane has e on one side, overlapping the cell on
// that side, and that pair is not skipped either. So the interiors of C's cells glued through
// their shared faces form a connected set disjoint from B, on which w is constant; (2)
// finds w(p) = 1, hence w = 1 on every cell of C, for every C: no two cells interpenetrate.
// Sampling one point per connected component of B instead would not do: a block swallowing
// a cavity of another has its faces inside the other's cells and the cavity wall inside its
// own, and its cells' centroids can lie in the cavity (cell_overlap_test.cpp).
// When the certificate finds an overlap (or does not apply), the exhaustive search runs so
// that every pair is listed; `vobench validate --exhaustive` runs only the reference.
// Cost on the 4.5M-cell helix: 295k boundary triangles, 13.5M (triangle, cell) box pairs,
// 0.64M exact cell tests, certified clean in 3.6-3.8 s of CPU against 93-102 s for the
// exhaustive search: the 10 s aim is met by the search; the whole `vobench validate`
// command (mesh generation, cell validation, faces) still takes 12-15 s user
// (docs/design-notes.md).
//
// Warped quads. The search above models a cell as the hull of its vertices; the oracle
// (harness/raster/cell_clip.h) models it as the intersection of its face half-spaces, a
// non-planar quad taken as one plane (cell_planes.h). For planar faces the two agree up to
// rounding. For warped quads they differ near the warped corners, and two cells that share
// only an edge or a vertex can overlap as the oracle models them while their hulls only
// touch: `vobench check` then refuses the input and `validate` would pass it. So for every
// candidate pair in which some cell has a quad that is not exactly planar, the exhaustive
// search also decides the pair in the oracle's model: the largest t such that an
// axis-aligned cube of half-side t fits in both cells' half-spaces (a linear program:
// n_i.x + t ||n_i||_1 <= n_i.o_i over the faces of both, solved exactly with CGAL's QP
// solver on CGAL::Gmpzf), reported when 2t exceeds the oracle's threshold,
// kOverlapRelative * scene radius. Every ray through the cube's centre crosses both cells
// for at least 2t, so such a pair is refused by the oracle at any view whose samples pass
// near there; an overlap thinner than the threshold is left alone, as the oracle leaves it.
// (Oblique rays through a thin sliver can see more than 2t, so an overlap within a small
// factor of the threshold may be refused by one and passed by the other.)
// A cell with a warped quad gets a candidate box that also holds its model polyhedron,
// which may reach past its vertices. Before the LP, a filter in doubles with error bounds
// (cell_model_overlap.cpp) settles the pairs that a face plane of one keeps within a
// quarter of the threshold of the other's model vertices; all pairs of a mesh whose quads
// are planar only up to rounding end there.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include <string>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/mesh_faces.h"

namespace vob {

// True when the interiors of cells a and b intersect (a != b).
bool cells_interpenetrate(const CellMesh& mesh, int32_t a, int32_t b);

// The fast path's verdict (see the comment at the top).
struct OverlapCertificate {
  enum Result { NotRun, Clean, Overlap, Undecided } result = NotRun;
  std::pair<int32_t, int32_t> witness{-1, -1};  // Overlap: the smallest interpenetrating pair found
  std::string why;                               // Undecided: the reason
  int64_t boundary_triangles = 0;   // (1): boundary faces as triangles
  int64_t triangle_cell_pairs = 0;  //      (triangle, cell) whose closed boxes meet
  int64_t contact_pairs = 0;        //      cell pairs left for the exact test
  int64_t components = 0;           // (2): face-connected components of cells
  int64_t nesting_pairs = 0;        //      cells whose box holds a component's sample point
  double seconds = 0;      // wall
  double cpu_seconds = 0;  // the process's CPU time meanwhile (all threads)
};

// True: the mesh has no interpenetrating cells (proven); Overlap: it has (the witness);
// Undecided: the argument does not apply (a non-planar quad). `faces` are the mesh's faces
// (build_mesh_faces), whose checks the argument relies on.
OverlapCertificate certify_cells_disjoint(const CellMesh& mesh, const MeshFaces& faces);

// A pair decided in the oracle's model (see "Warped quads" above).
struct ModelOverlap {
  bool overlap = false;   // 2t > tol
  double thickness = 0;   // 2t (an upper bound when `filtered`; +inf when unbounded)
  bool filtered = false;  // settled by the filter, no LP
  bool solved = false;    // the exact LP ran
};

// True overlap when cells a and b, as the oracle models them, hold a common axis-aligned
// cube of side more than tol (model_overlap_tolerance: the oracle's threshold).
ModelOverlap cells_overlap_as_modelled(const CellMesh& mesh, int32_t a, int32_t b, double tol);
double model_overlap_tolerance(const CellMesh& mesh);  // kOverlapRelative * bounds radius

// The most warped quad of cell c: local face index (-1: every quad is exactly planar) and
// the largest distance of its points from the oracle's plane over its largest extent.
struct QuadWarp {
  int face = -1;
  double relative = 0;
};
QuadWarp worst_quad_warp(const CellMesh& mesh, int32_t c);
// "their quads are not planar (cell 75 face 3 warped by 0.0021 of its size) and the oracle
// takes each quad as one plane", or "" when neither cell has a non-planar quad.
std::string warped_quad_cause(const CellMesh& mesh, int32_t a, int32_t b);

struct CellOverlapReport {
  std::vector<std::pair<int32_t, int32_t>> pairs;  // (smaller id, larger id), sorted
  // The pairs of `pairs` whose hulls do not interpenetrate but which overlap as the oracle
  // models them (warped quads), with their thickness 2t; sorted.
  struct ModelPair {
    std::pair<int32_t, int32_t> cells;
    double thickness;
  };
  std::vector<ModelPair> model_pairs;
  int64_t warped_cells = 0;  // cells with a quad that is not exactly planar
  int64_t model_tests = 0;   // candidate pairs decided in the oracle's model
  int64_t model_lps = 0;     // of which by the exact LP (not settled by the filter)
  double model_tolerance = 0;  // 2t must exceed this (the oracle's threshold)
  int64_t candidates = 0;                           // box pairs decided exactly
  double box_seconds = 0;                           // box intersection, including the
  double total_seconds = 0;                         // exact tests it overlaps with
  std::string method = "exhaustive";  // or "boundary": certified clean, nothing to list
  OverlapCertificate certificate;     // the fast path's, when it ran
};

// Every interpenetrating pair of the mesh. The box enumeration runs on one thread and hands
// batches of candidates to TBB for the exact tests, which run while it continues.
// This is the reference (exhaustive) search.
CellOverlapReport find_overlapping_cells(const CellMesh& mesh);

enum class OverlapSearch { Fast, Exhaustive };

// Fast: certify_cells_disjoint, and only when it does not certify a clean mesh (an overlap
// exists, or it is undecided) the exhaustive search, so that every pair is listed.
// Exhaustive: find_overlapping_cells. Either way `pairs` is complete.
CellOverlapReport check_overlapping_cells(const CellMesh& mesh, const MeshFaces& faces,
                                          OverlapSearch search = OverlapSearch::Fast);

// One line naming the first pair, e.g. "source: cells 12 and 4071 overlap (...)" - the
// InputError message of `--validate full`; throws nothing. A pair found in the oracle's
// model only is described with its thickness and warped_quad_cause (pass the mesh).
std::string describe_overlap(const std::string& source, const CellOverlapReport& r,
                             const CellMesh* mesh = nullptr);
// The thickness of pair (a, b) if it is one of r.model_pairs, else a negative number.
double model_pair_thickness(const CellOverlapReport& r, std::pair<int32_t, int32_t> cells);

}  // namespace vob
