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
// Cost: the box stage gives ~44 candidates per cell on the helix (198M pairs for 4.5M
// cells), every one decided exactly; about 100 s of CPU for 4.5M cells on this machine
// (docs/design-notes.md), far from a 10 s aim.
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

struct CellOverlapReport {
  std::vector<std::pair<int32_t, int32_t>> pairs;  // (smaller id, larger id), sorted
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
// InputError message of `--validate full`; throws nothing.
std::string describe_overlap(const std::string& source, const CellOverlapReport& r);

}  // namespace vob
