// Triangle-soup spheres: `sphere` is an icosahedron subdivided `subdiv` times (20*4^subdiv
// triangles, counter-clockwise seen from outside); `spheres` is three groups of three
// nested spheres (radii 1, 0.66, 0.33) placed so that groups hide each other from most
// views: up to 18 surfaces along one ray, for depth complexity.
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

// Appends a subdivided icosahedron of `radius` around `centre`.
void append_icosphere(TriangleSoup& soup, Vec3 centre, double radius, int subdiv);
Scene make_sphere(Params& p);   // subdiv=3
Scene make_spheres(Params& p);  // subdiv=2

}  // namespace vob
