// Hard cases about the view (hard_case = true): a block of n^3 unit hexahedra with integer
// corner coordinates, each split into six tetrahedra (Kuhn split: face planes x=c, y=c,
// z=c, x-y=c, y-z=c, x-z=c for integers c), and cameras that make it hard.
//   edge-on       orthographic views exactly along x, y and z: every face in a plane that
//                 holds the view direction projects to a segment; in the second z view
//                 the eye is shifted half a pixel so pixel centres land exactly on the
//                 projected grid lines (pixel size is a power of two).
//   eye-in-plane  perspective views from integer eyes that lie in many face planes
//                 (one on the block's main diagonal, in the planes x=y, y=z, x=z).
//   eye-inside    perspective views from inside the mesh: a generic interior point and an
//                 interior mesh vertex.
#pragma once
#include <vector>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

Scene make_edge_on(Params& p);       // n=8
Scene make_eye_in_plane(Params& p);  // n=6
Scene make_eye_inside(Params& p);    // n=6
std::vector<Camera> edge_on_views(const Scene& s, int width, int height);
std::vector<Camera> eye_in_plane_views(const Scene& s, int width, int height);
std::vector<Camera> eye_inside_views(const Scene& s, int width, int height);

}  // namespace vob
