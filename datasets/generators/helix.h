// `helix` (Cook et al. 2004, Fig. 8): "a green inner helix surrounded by a pink outer
// helix", the configuration on which MPVONC fails. Both tubes follow one centre line (coil
// radius 2, pitch 3, about the z axis). The outer tube is hollow: an annulus from its bore
// (radius 0.6) to radius 1, scalars 0.8..0.7 (pink). The inner tube is solid, radius 0.599,
// scalars 0.3..0.2 (green), and runs inside the bore: a film of empty space 0.001 thick
// separates the tubes everywhere; they share no faces.
//
// Why MPVONC fails here. It outputs a cell during the DFS of the first root (exterior cell
// with a front-facing exterior face, by decreasing centroid distance) from which the cell is
// reachable through behind arrows. Arrows never cross from one tube to the other, so a cell
// A and the cell B it hides in the other tube come out in the order of their roots. In a
// mesh of small cells a root reaches only cells behind it, so that order is right wherever
// the ray-gap from A to B is longer than the cells are deep: with the tubes >= 0.4 apart (two
// separate coils, or a bore of 0.7 around a tube of 0.3) no view of 14 fails. Across the
// film the ray-gap is far shorter than any cell (cells are ~0.03 even at 50M), and where a
// ray crosses the film obliquely the root that reaches A can have its centroid farther away
// than the root in front of B: A is drawn first and B over it. Green drawn over the pink
// wall in front of it is Fig. 8b; pink drawn over green also occurs.
//
// Each tube is a triangulated disk (inner) or annulus (outer) of `sectors` sectors, at the
// same angles in both, swept along the centre line in `steps` steps with a
// rotation-minimising frame; every swept triangle is a prism cut into three tetrahedra with
// the conforming min-id rule (prism_split.h).
//
// Resolution. By default cells are near-isotropic: the exterior faces b grow as n^(2/3)
// (70,226 at 450k). Cook et al. Table 1 gives n and b of each helix but not how it was cut
// (b/n is 1/15.5 at 450k, 1/39 at 3.57M: cells thin across the tube). With `faces` the
// generator picks sectors, radial cells and steps whose n and b are both nearest the two
// targets (within 1% where the shape allows, else InputError above 5%), cells square on the
// tube's surface (arc between sectors ~ step length), the radial split taking the rest.
// Thin cells in a bend can fail the exact convexity check: Table 1's counts at 3 turns pass
// (vobench validate), but e.g. cells=1485000 faces=59500 turns=2 is refused at load.
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

// The fixed shape before `offset`. Centre line: helix_centre(t), t in [0, 2 pi turns].
struct HelixShape {
  double coil_radius = 2.0, pitch = 3.0;
  double inner_radius = 0.599;  // solid inner tube
  double hole_radius = 0.6;     // bore of the outer tube
  double outer_radius = 1.0;
};
Vec3 helix_centre(double t);  // (coil_radius cos t, coil_radius sin t, pitch t / 2 pi)

struct HelixResolution {
  int sectors = 3;       // around both tubes
  int inner_rings = 1;   // inner disk: a centre fan, then quads
  int outer_layers = 1;  // annulus: quads only
  int steps = 1;         // prisms along the centre line
  int64_t per_step() const {
    return int64_t(3) * sectors * ((2 * inner_rings - 1) + 2 * outer_layers);
  }
  int64_t cells() const { return per_step() * steps; }
};
// The resolution whose cell count is nearest `cells` with near-isotropic cells and at
// least 6 steps per turn. InputError when `cells` is below the smallest helix.
HelixResolution helix_resolution(int cells, int turns);
// The resolution whose cells and exterior faces are both nearest (cells, faces): among
// those within 1% of both, the one whose surface cells are squarest; InputError when none
// is within 5%.
HelixResolution helix_resolution_for_faces(int cells, int faces, int turns);
int64_t helix_exterior_faces(const HelixResolution& r);  // three tube surfaces and two ends
int helix_min_cells(int turns);

struct HelixSpec {
  int cells = 20000, turns = 3;
  Vec3 offset{0, 0, 0};  // added to every coordinate (the `offset` hard case)
  int faces = 0;         // > 0: target exterior faces b (helix_resolution_for_faces)
};
CellMesh make_helix_mesh(const HelixSpec& s);
// cells=20000 turns=3 faces=0 (near-isotropic) shuffle=0 (> 0: cells and points renumbered
// at random from that seed, shuffle.h).
Scene make_helix(Params& p);

}  // namespace vob
