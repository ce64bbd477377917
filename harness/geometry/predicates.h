// Robust geometric predicates. Signs come from CGAL's filtered exact kernels: a fast
// interval filter, exact arithmetic only when the double result is too close to call.
// Kept behind this header so that CGAL is compiled in one translation unit only.
#pragma once
#include <cstddef>

#include "harness/geometry/vec3.h"

namespace vob {

// Sign of the determinant | b-a, c-a, d-a |: +1 when d lies on the side of plane (a,b,c)
// that its right-hand normal (b-a)x(c-a) points to, -1 on the other side, 0 on the plane.
int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// Sign of ((b-a) x (c-a)) . dir, exactly (used for orthographic views).
int orient_direction(Vec3 a, Vec3 b, Vec3 c, Vec3 dir);

// Sign of the 2-D orientation of (a, b, c) given as xy pairs: +1 counter-clockwise.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// True when a, b and c lie on one line (or coincide), exactly.
bool collinear(Vec3 a, Vec3 b, Vec3 c);

// The fan of polygon v[0..n) (n >= 3) from v[0]: for each fan triangle (v[0], v[q], v[q+1]),
// q = 1 .. n-2, facing[q - 1] gets the sign of ((v[q] - v[0]) x (v[q+1] - v[0])) . N, N the
// polygon's Newell normal (the sum of those cross products), exactly. Returns false (facing
// all 0) when N is exactly zero.
bool fan_facings(const Vec3* v, size_t n, int* facing);

}  // namespace vob
