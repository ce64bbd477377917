// The exact pair test of cell_overlap.h: two cells interpenetrate unless a face-triangle
// plane of one or a plane spanned by an edge of each separates them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <CGAL/Mpzf.h>

#include "harness/scene/cell_overlap.h"
#include "harness/scene/cell_overlap_detail.h"

namespace vob {
namespace overlap_detail {

// Exact sign of det(u1 - u0, v1 - v0, x - o). In doubles first, with Shewchuk's forward
// error bound for a 3x3 determinant of rounded differences (his orient3d bound; the rows
// here have different subtrahends, which his analysis does not use); exact in CGAL::Mpzf
// (exact +, -, * on doubles) when the bound cannot call it.
int sign_det(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1, const Vec3& o,
             const Vec3& x) {
  const double ux = u1.x - u0.x, uy = u1.y - u0.y, uz = u1.z - u0.z;
  const double vx = v1.x - v0.x, vy = v1.y - v0.y, vz = v1.z - v0.z;
  const double wx = x.x - o.x, wy = x.y - o.y, wz = x.z - o.z;
  const double a = vy * wz, b = vz * wy, c = vz * wx, d = vx * wz, e = vx * wy, f = vy * wx;
  const double det = ux * (a - b) + uy * (c - d) + uz * (e - f);
  const double perm = std::abs(ux) * (std::abs(a) + std::abs(b)) +
                      std::abs(uy) * (std::abs(c) + std::abs(d)) +
                      std::abs(uz) * (std::abs(e) + std::abs(f));
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;  // 2^-53
  constexpr double bound = (7.0 + 56.0 * eps) * eps;
  // Below ~1e-250 products may underflow and the bound no longer holds: go exact.
  if (perm > 1e-250) {
    if (det > bound * perm) return 1;
    if (-det > bound * perm) return -1;
  }
  // A zero row (equal points: a double difference is zero only then) makes det exactly 0.
  if ((ux == 0 && uy == 0 && uz == 0) || (vx == 0 && vy == 0 && vz == 0) ||
      (wx == 0 && wy == 0 && wz == 0))
    return 0;
  using M = CGAL::Mpzf;
  const M Ux = M(u1.x) - M(u0.x), Uy = M(u1.y) - M(u0.y), Uz = M(u1.z) - M(u0.z);
  const M Vx = M(v1.x) - M(v0.x), Vy = M(v1.y) - M(v0.y), Vz = M(v1.z) - M(v0.z);
  const M Wx = M(x.x) - M(o.x), Wy = M(x.y) - M(o.y), Wz = M(x.z) - M(o.z);
  const M D = Ux * (Vy * Wz - Vz * Wy) + Uy * (Vz * Wx - Vx * Wz) + Uz * (Vx * Wy - Vy * Wx);
  return int(D.sign());
}

TypeShape::TypeShape(CellType t) {
  const LocalFaces& lf = cell_local_faces(t);
  for (int f = 0; f < lf.count; ++f) {
    const int* v = lf.v[f];
    const int n = lf.size[f];
    for (int i = 0; i < n; ++i) add_edge(v[i], v[(i + 1) % n]);
    add_tri(v[0], v[1], v[2]);
    if (n == 4) add_tri(v[0], v[2], v[3]);
  }
}

void TypeShape::add_edge(int a, int b) {
  if (a > b) std::swap(a, b);
  for (int i = 0; i < nedge; ++i)
    if (edge[i][0] == a && edge[i][1] == b) return;
  edge[nedge][0] = a, edge[nedge][1] = b, ++nedge;
}

const TypeShape& type_shape(CellType t) {
  static const TypeShape tet(CellType::Tetra), hex(CellType::Hexahedron),
      wedge(CellType::Wedge), pyramid(CellType::Pyramid);
  switch (t) {
    case CellType::Tetra: return tet;
    case CellType::Hexahedron: return hex;
    case CellType::Wedge: return wedge;
    default: return pyramid;
  }
}

uint8_t non_planar_quads(const CellMesh& mesh, int32_t c) {
  if (mesh.types[c] == CellType::Tetra) return 0;
  const int32_t* p = mesh.cell_points(c);
  const LocalFaces& lf = cell_local_faces(mesh.types[c]);
  uint8_t mask = 0;
  for (int f = 0; f < lf.count; ++f) {
    if (lf.size[f] != 4) continue;
    const Vec3& a = mesh.points[p[lf.v[f][0]]];
    const Vec3& b = mesh.points[p[lf.v[f][1]]];
    const Vec3& d = mesh.points[p[lf.v[f][2]]];
    const Vec3& e = mesh.points[p[lf.v[f][3]]];
    // A quad in a coordinate plane is planar without arithmetic (sign_det would need its
    // exact fallback to say 0, which grids of axis-aligned hexahedra would pay per quad).
    bool in_axis_plane = false;
    for (int k = 0; k < 3; ++k) in_axis_plane |= a[k] == b[k] && a[k] == d[k] && a[k] == e[k];
    if (!in_axis_plane && sign_det(a, b, a, d, a, e) != 0) mask |= uint8_t(1u << f);
  }
  return mask;
}

}  // namespace overlap_detail

namespace {

using overlap_detail::non_planar_quads;
using overlap_detail::sign_det;
using overlap_detail::type_shape;
using overlap_detail::TypeShape;

bool same_point(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// A cell as the candidate planes need it: vertices, face triangles, edges. The type's
// tables are used in place unless a non-planar quad adds triangles and diagonals.
struct CellShape {
  int n = 0, ntri = 0, nedge = 0;
  Vec3 p[8];
  const int (*tri)[3];
  const int (*edge)[2];
  int own_tri[24][3];   // 6 faces x up to 4 triangles (both diagonals of non-planar quads)
  int own_edge[24][2];  // 12 edges + 12 diagonals at most
  const LocalFaces* faces = nullptr;
  bool non_planar = false;  // some quad face is not planar

  // `quads`: non_planar_quads(mesh, c), computed here when negative.
  CellShape(const CellMesh& mesh, int32_t c, int quads = -1) {
    const int32_t* ids = mesh.cell_points(c);
    n = mesh.cell_size(c);
    for (int i = 0; i < n; ++i) p[i] = mesh.points[ids[i]];
    const TypeShape& ts = type_shape(mesh.types[c]);
    ntri = ts.ntri, nedge = ts.nedge, tri = ts.tri, edge = ts.edge;
    faces = &cell_local_faces(mesh.types[c]);
    if (mesh.types[c] == CellType::Tetra) return;
    if (quads < 0) quads = non_planar_quads(mesh, c);
    // A non-planar quad: the hull takes one of its diagonals, which one depends on the
    // other vertices; try both.
    const LocalFaces& lf = cell_local_faces(mesh.types[c]);
    for (int f = 0; f < lf.count; ++f) {
      const int* v = lf.v[f];
      if (!(quads >> f & 1)) continue;
      non_planar = true;
      if (tri == ts.tri) {
        std::copy(&ts.tri[0][0], &ts.tri[0][0] + 3 * ntri, &own_tri[0][0]);
        std::copy(&ts.edge[0][0], &ts.edge[0][0] + 2 * nedge, &own_edge[0][0]);
        tri = own_tri, edge = own_edge;
      }
      const int more[2][3] = {{v[0], v[1], v[3]}, {v[1], v[2], v[3]}};
      for (const auto& t : more) std::copy(t, t + 3, own_tri[ntri++]);
      own_edge[nedge][0] = v[0], own_edge[nedge][1] = v[2], ++nedge;
      own_edge[nedge][0] = v[1], own_edge[nedge][1] = v[3], ++nedge;
    }
  }
  CellShape(const CellShape&) = delete;  // tri/edge may point into the object itself
};

// Side of every point of `s` for a plane given by `side_of` (exact signs): -1 or +1 when
// all points are on that closed side (at least one strictly), 0 when all lie on the plane,
// 2 when the points straddle the plane.
template <class SideOf>
int side_of_all(const CellShape& s, SideOf&& side_of) {
  int side = 0;
  for (int i = 0; i < s.n; ++i) {
    const int si = side_of(s.p[i]);
    if (si == 0) continue;
    if (side == 0) side = si;
    else if (si != side) return 2;
  }
  return side;
}

// True when the plane separates P and Q: each on one closed side, the sides opposite.
// A degenerate plane (all determinants zero) puts both "on" it and separates nothing.
template <class SideOf>
bool separates(const CellShape& P, const CellShape& Q, SideOf&& side_of) {
  const int q = side_of_all(Q, side_of);
  if (q == 2 || q == 0) return false;
  const int p = side_of_all(P, side_of);
  return p != 2 && p != 0 && p != q;
}

bool face_plane_separates(const CellShape& F, const CellShape& other, int t) {
  const Vec3& a = F.p[F.tri[t][0]];
  const Vec3& b = F.p[F.tri[t][1]];
  const Vec3& c = F.p[F.tri[t][2]];
  auto side_of = [&](const Vec3& x) {
    if (same_point(x, a) || same_point(x, b) || same_point(x, c)) return 0;
    return sign_det(a, b, a, c, a, x);
  };
  return separates(F, other, side_of);
}

bool edge_plane_separates(const CellShape& P, const CellShape& Q, int i, int j) {
  const Vec3& a = P.p[P.edge[i][0]];
  const Vec3& b = P.p[P.edge[i][1]];
  const Vec3& c = Q.p[Q.edge[j][0]];
  const Vec3& d = Q.p[Q.edge[j][1]];
  // Exact zeros known without arithmetic: x is a or b; or x is c or d while the other of
  // c, d is a or b (then x - a is a combination of b - a and d - c).
  const bool cd_touches_ab = same_point(c, a) || same_point(c, b) || same_point(d, a) || same_point(d, b);
  auto side_of = [&](const Vec3& x) {
    if (same_point(x, a) || same_point(x, b)) return 0;
    if (cd_touches_ab && (same_point(x, c) || same_point(x, d))) return 0;
    return sign_det(a, b, c, d, a, x);
  };
  return separates(P, Q, side_of);
}

// Index of the face of Q with the same vertex coordinates as face f of P, or -1.
int matching_face(const CellShape& P, int f, const CellShape& Q) {
  const int k = P.faces->size[f];
  for (int g = 0; g < Q.faces->count; ++g) {
    if (Q.faces->size[g] != k) continue;
    int found = 0;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        if (same_point(P.p[P.faces->v[f][i]], Q.p[Q.faces->v[g][j]])) ++found;
    if (found == k) return g;
  }
  return -1;
}

// Every vertex of `other` that is not on face f of `F` lies strictly outside both triangle
// planes (0,1,2), (0,2,3) of that face (outward normals: positive determinant).
bool beyond_face(const CellShape& F, int f, const CellShape& other) {
  const int* v = F.faces->v[f];
  const int k = F.faces->size[f];
  for (int i = 0; i < other.n; ++i) {
    const Vec3& x = other.p[i];
    bool on_face = false;
    for (int j = 0; j < k; ++j) on_face |= same_point(x, F.p[v[j]]);
    if (on_face) continue;
    for (int t = 0; t + 2 < k; ++t) {
      const Vec3& a = F.p[v[0]];
      if (sign_det(a, F.p[v[t + 1]], a, F.p[v[t + 2]], a, x) <= 0) return false;
    }
  }
  return true;
}

// Two cells sharing a non-planar quad cannot both be the convex hulls of their vertices
// without overlapping in the sliver between the quad's two triangulations; the mesh means
// the quad as one curved face between them. So cells that share a whole face (same
// coordinates) and lie beyond it from each other are neighbours, not an overlap.
bool neighbours_across_a_face(const CellShape& P, const CellShape& Q) {
  for (int f = 0; f < P.faces->count; ++f) {
    const int g = matching_face(P, f, Q);
    if (g >= 0 && beyond_face(P, f, Q) && beyond_face(Q, g, P)) return true;
  }
  return false;
}

bool shapes_interpenetrate(const CellShape& P, const CellShape& Q) {
  if ((P.non_planar || Q.non_planar) && neighbours_across_a_face(P, Q)) return false;
  for (int t = 0; t < P.ntri; ++t)
    if (face_plane_separates(P, Q, t)) return false;
  for (int t = 0; t < Q.ntri; ++t)
    if (face_plane_separates(Q, P, t)) return false;
  for (int i = 0; i < P.nedge; ++i)
    for (int j = 0; j < Q.nedge; ++j)
      if (edge_plane_separates(P, Q, i, j)) return false;
  return true;
}

}  // namespace

bool cells_interpenetrate(const CellMesh& mesh, int32_t a, int32_t b) {
  return shapes_interpenetrate(CellShape(mesh, a), CellShape(mesh, b));
}

namespace overlap_detail {
bool cells_interpenetrate(const CellMesh& mesh, int32_t a, int32_t b, uint8_t quads_a, uint8_t quads_b) {
  return shapes_interpenetrate(CellShape(mesh, a, quads_a), CellShape(mesh, b, quads_b));
}
}  // namespace overlap_detail

}  // namespace vob
