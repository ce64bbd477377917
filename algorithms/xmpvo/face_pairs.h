// Exact view-dependent geometry of exterior faces, shared by XMPVO and BSP-XMPVO.
// Every decision of sign (which side of a projected edge, which face is in front) is an
// exact predicate on the input doubles (orient3d / orient_direction, CGAL filtered), so
// the relations built from these answers do not depend on rounding.
//
// A "projected edge line" of a perspective view is the plane through the eye and the edge;
// of an orthographic view, the plane through the edge parallel to the view direction.
// Faces are convex planar polygons given by their vertices (3 or 4, as stored in MeshFaces).
#pragma once
#include <cstdint>

#include "harness/geometry/vec3.h"
#include "harness/view/camera.h"

namespace vob::xmpvo {

// The projective setting of one view: rays from `eye` (perspective) or along `dir`
// (orthographic, dir = forward).
struct ViewGeometry {
  bool ortho = false;
  Vec3 eye;
  Vec3 dir;
  static ViewGeometry of(const Camera& view);
};

// Side of p relative to the projected line of edge (a, b), exactly: +1 / -1 / 0 (p's ray
// lies in the plane through the eye and the edge). The sign is that of
// orient3d(eye, a, b, p) for perspective views; for orthographic views the sign of the
// same plane's orientation with the eye replaced by a point at infinity along -dir.
int edge_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 p);

// Side of the eye relative to the plane of face (a, b, c): +1 when the eye sees the side
// the right-hand normal (b-a)x(c-a) points to, -1 the other, 0 edge-on.
int eye_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c);

// Whether the projections of convex faces A and B share an open set (interiors overlap),
// exactly; touching along an edge or at a point is not overlap. Faces must be entirely in
// front of a perspective eye (callers skip or report the others).
bool projections_overlap(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb);

// Depth order of A and B over the overlap of their projections (which must share an open
// set): -1 when A is in front of B (nearer the eye along every ray through the overlap),
// +1 when B is in front, 0 when it cannot be decided because the faces intersect, or are
// coplanar and face the same way (invalid input, reported by the caller).
// Coplanar exterior faces facing opposite ways (volumes touching face to face) are at
// equal depth on every ray through the overlap; there the ray leaves the cell of the
// back-facing face and enters the cell of the front-facing one, so the back-facing face
// counts as in front: see coplanar_order.
// Two triangles that share one vertex and straddle each other's planes (faces of a curved
// boundary around a vertex, seen across a fold) are decided by orientation signs at the
// shared vertex alone; other straddling pairs by clipping A at B's plane in exact
// constructions.
int depth_order(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb);
// depth_order without the shared-vertex shortcut: every straddling pair clipped (the
// reference the shortcut is tested against).
int depth_order_by_clipping(const ViewGeometry& g, const Vec3* a, int na, const Vec3* b, int nb);

// The tie rule for coplanar exterior faces A and B (outward normals by the right-hand
// rule of their first three vertices) whose projections overlap: -1 when A is back-facing
// and B front-facing (A's cell lies on the eye's side of the plane, B's behind it), +1 the
// other way round, 0 when both face the same way (their cells would overlap) or edge-on.
// Exact: two orientation signs, no construction.
int coplanar_order(const ViewGeometry& g, const Vec3* a, const Vec3* b);

// ---- Additions for XMPVO's arrangement and the stability study ----

// D(x, y, z): the determinant whose sign edge_side(g, x, y, z) returns (orient3d(eye, x, y,
// z) or ((y-x) x (z-x)).dir). It is affine in each argument, which is what lets the side of
// an edge crossing be written without constructing the crossing point.
//
// Side of q relative to the projected line through X and p, where X is the point of segment
// (a, b) whose projection lies on the projected line of (c, d): the sign of D(X, p, q),
// exactly. Precondition: edge_side(c, d, a) and edge_side(c, d, b) are non-zero and
// opposite (a proper crossing). With p, q an edge, this is the side of the crossing
// vertex relative to that edge's projected line; with p a point, the orientation of the
// directions from the crossing to p and to q.
int crossing_side(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q);

// Which of the planes of faces A and B (their first three vertices) the ray through the
// projection of p meets first: -1 A's, +1 B's, 0 the same point (or a plane holds the ray).
// Where both faces cover that ray (p inside both projections, or on a boundary with the
// planes met at different points) this is their depth order over the whole overlap --
// a cheap exact shortcut of depth_order at an arrangement vertex.
int plane_order_at(const ViewGeometry& g, const Vec3* a, const Vec3* b, Vec3 p);
// The same along the ray through the crossing of segment (c0, c1) with the projected line
// of (d0, d1) (edge_side(d0, d1, c0) and edge_side(d0, d1, c1) non-zero and opposite).
int plane_order_at_crossing(const ViewGeometry& g, const Vec3* a, const Vec3* b, Vec3 c0, Vec3 c1,
                            Vec3 d0, Vec3 d1);

// The ray through an arrangement vertex with the vertex's share of the two tests above
// precomputed (a query asks many of them at one vertex), and a face plane with its normal
// and that normal's rounding bound precomputed (view-independent).
struct VertexRay {
  ViewGeometry g;
  bool crossing = false;
  Vec3 p[4];  // the point, or a, b, c, d of the crossing of (a, b) with (c, d)
  // Filter values (double, rounding bound) of D(c, d, a), D(c, d, b) and the homogeneous
  // ray point (w; h) of plane_order_at_crossing.
  double oa[2] = {0, 0}, ob[2] = {0, 0}, w[2] = {1, 0}, h[3][2] = {};
  static VertexRay at_point(const ViewGeometry& g, Vec3 p);
  static VertexRay at_crossing(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d);
};
struct FacePlane {
  Vec3 f[3];               // the face's first three vertices
  double n[3][2] = {};     // (f1-f0) x (f2-f0) and its rounding bound
  static FacePlane of(const Vec3* face);
};
// = crossing_side / edge_side(g, p, q, point) with the vertex's ray; exact.
int vertex_side(const VertexRay& r, Vec3 p, Vec3 q);
// = plane_order_at / plane_order_at_crossing; exact.
int vertex_plane_order(const VertexRay& r, const FacePlane& a, const FacePlane& b);

// The same signs in plain double arithmetic: no filter, no exact fallback. Used by the
// `predicates=double` mode of XMPVO and by the stability study; never by exact code paths.
int edge_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 p);
int eye_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c);
int crossing_side_double(const ViewGeometry& g, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q);

}  // namespace vob::xmpvo
