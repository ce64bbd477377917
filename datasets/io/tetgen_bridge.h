// Tetrahedralizing closed surfaces with the `tetgen` program (VOB_TETGEN), run as a
// subprocess in a private folder. TetGen fails in two quiet ways, both turned into
// InputError here: a self-intersecting surface makes it abort (we then rerun it with -d
// to name the intersecting facets), and an open surface gives 0 tetrahedra and no .ele.
#pragma once
#include <string>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/triangle_soup.h"

namespace vob {

constexpr const char* kDefaultTetgenSwitches = "pq1.414";

// InputError naming the first edge that is not shared by an even number of triangles
// (an open or non-manifold border): TetGen needs a closed surface.
void check_closed_surface(const TriangleSoup& s, const std::string& source);

// InputError unless every connected piece of the surface can bound a volume: a piece whose
// points all lie in one plane (exactly), or a triangle given twice (same three points), encloses
// none, and TetGen 1.5 aborts on such input (`Assertion 'maxz > 0'` for a piece flat in an axis,
// SIGSEGV for a doubled triangle, a bogus self-intersection for a tilted flat one). Checked by
// tetrahedralize_surface before TetGen runs.
void check_encloses_volume(const TriangleSoup& s, const std::string& source);

// Runs `tetgen -<switches> surface.off` and reads its .node/.ele. Switches must hold 'p'
// (mesh the surface) and must not hold d, r, N, E, I, o (no tetrahedra, other files or 10-node output). With a
// non-empty cache_key the result is kept in cache_dir()/tetgen/<key>-<hash of switches>
// and reused. Points get no scalars (the caller decides).
CellMesh tetrahedralize_surface(const TriangleSoup& surface, const std::string& source,
                                const std::string& switches, const std::string& cache_key = "");

}  // namespace vob
