// `zoo` (Cook et al. 2004, Fig. 14): six disconnected latitude-longitude spheres built in
// layers of zoo cells. The layer touching the centre has tetrahedra at the poles (centre +
// polar cap triangle) and pyramids elsewhere (centre + lat-long quad); each outer layer has
// wedges at the poles and hexahedra elsewhere. Every face is planar in exact arithmetic
// (lat-long quads are symmetric trapezoids; side faces lie in planes through the centre)
// and every cell is a convex frustum of a cone from the centre.
// Per sphere: nlon = 20*scale, nlat = 10*scale, layers = 6*scale; at scale 1 the six
// spheres hold 240 tetrahedra, 960 pyramids, 1200 wedges and 4800 hexahedra.
// The unit spheres sit on the vertices of an octahedron (centres +-1.6 on each axis), so
// from most directions some sphere hides another across empty space.
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

CellMesh make_zoo_mesh(int scale);
Scene make_zoo(Params& p);  // scale=1

}  // namespace vob
