// Hard cases with visibility cycles (hard_case = true), each with the views that show it.
//   cycle         a connected ring of `cells` convex hexahedra around the z axis. All cell
//                 edges run towards one apex (the origin): at z=1 the ring is an annulus
//                 (radii 1..2) cut by `cells` segments twisted by `twist` degrees, and each
//                 cell is the frustum of the cone over its quad between z=1 and z=2. Every
//                 face is planar, and the separating faces are tilted like propeller blades
//                 (planes through the apex, not through the axis), so from any eye on the
//                 positive z axis each shared face is seen from the same rotational side:
//                 the MPVO face arrows form one directed cycle.
//   cycle-sticks  three disjoint long thin sticks (hexahedra) on the sides of a triangle,
//                 each rising along its length, so that seen from above stick i lies over
//                 stick i+1 where they cross (the classic three-sticks cycle).
#pragma once
#include <vector>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

Scene make_cycle(Params& p);         // cells=6 twist=30
Scene make_cycle_sticks(Params& p);  // no parameters
std::vector<Camera> cycle_views(const Scene& s, int width, int height);
std::vector<Camera> cycle_sticks_views(const Scene& s, int width, int height);

}  // namespace vob
