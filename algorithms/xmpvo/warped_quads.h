// XMPVO's arrangement and depth tests take every exterior face as a planar convex polygon
// (face_pairs.h). The quads of real hexahedral and prism meshes are planar only to
// rounding (a structured box rotated by gmsh or VTK), and a warped quad's first-three-point
// plane does not hold its fourth point: two faces meeting at the box's silhouette were
// then undecided in depth, and the relation made from that answer closed a cycle (gmsh's
// rotated 3x3x3 hex box: 2 of 14 views with violations). Such quads are taken as their two
// triangles (0,1,2) and (0,2,3), the split cell validation tests and BSP-XMPVO builds from.
#pragma once
#include "harness/scene/exterior_faces.h"

namespace vob::xmpvo {

// The exterior faces with each quad that is not exactly planar (orient3d of its four points
// non-zero) replaced by its two triangles, both owned by the quad's cell and listed where
// the quad was. Returns the number of quads split; 0 leaves `out` untouched.
size_t split_warped_quads(const ExteriorFaces& in, ExteriorFaces& out);

}  // namespace vob::xmpvo
