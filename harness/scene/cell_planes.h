// The oracle's model of a cell: the intersection of its outward face half-spaces
// n.(x - o) <= 0, one plane per local face. The ray clipper (harness/raster/cell_clip.h)
// clips against exactly these planes, and `vobench validate` tests warped cells against
// them (cell_overlap.h), so both see the same cells.
//
// Face planes are Newell planes computed from the face's point ids in a canonical order
// (smallest id first, then towards its smaller neighbour), so the two cells sharing a face
// get exactly negated planes: at every sample they compute the same crossing parameter, and
// the segments of face neighbours meet without gap or overlap. The plane passes through the
// canonical first point (not the centroid, which /3 would round): a ray lying exactly in
// the plane then meets it at exactly zero. A planar face's plane holds all its points up to
// rounding; a non-planar quad is replaced by that plane, so the cell is not the hull of its
// vertices but a polyhedron whose faces near a warped quad cut or pass beside its corners.
// Two cells that share only an edge or a vertex of warped quads can then overlap (or leave a
// gap) near it, in a sliver about as thick as the warp.
#pragma once
#include <cstdint>

#include "harness/geometry/polygon_plane.h"
#include "harness/scene/cell_mesh.h"
#include "harness/scene/cell_types.h"

namespace vob {

// Far below any real cell's extent (a cell 1e-10 of the scene across is degenerate), far
// above the rounding noise of t (about 1e-15 of the eye distance) while the eye is within
// about 100 radii. The oracle drops segments not longer than this times the scene radius
// (cell_clip.h), or than kMinSegmentFarRelative times the largest t of the view when
// that is more.
constexpr double kMinSegmentRelative = 1e-10;
// t is measured from the eye (the eye plane), so it is known only to about 1e-15 of
// itself: an eye 1e9 away resolves t to 1e-7, far above 1e-10 of a small scene's radius.
// 100 times above that noise, the floor follows it (oracle_min_segment, cell_clip.h); for
// views from within 1000 radii (every view set with zoom >= 0.004) kMinSegmentRelative
// decides.
constexpr double kMinSegmentFarRelative = 1e-13;
// Beyond this many radii from the scene the floor would exceed 1e-4 of the scene: the
// oracle refuses such a view (cell scenes) rather than judge it on what is left.
constexpr double kMaxEyeRadii = 1e9;
// `vobench validate` reports warped cells whose model overlaps by more than this times the
// scene radius; the oracle, by more than half its segment floor (oracle.h says why half
// the shortest segment), which is this times the radius unless the eye is far.
constexpr double kOverlapRelative = 0.5 * kMinSegmentRelative;

struct CellPlanes {
  int count = 0;
  Vec3 n[6];  // outward normals (Newell's, not normalised)
  Vec3 o[6];  // a point of each face plane (its canonical first vertex)
};

// The face planes of cell c, face f being local face f (cell_local_faces).
inline void cell_face_planes(const CellMesh& mesh, int32_t c, CellPlanes& out) {
  const int32_t* p = mesh.cell_points(c);
  const LocalFaces& lf = cell_local_faces(mesh.types[c]);
  out.count = lf.count;
  for (int f = 0; f < lf.count; ++f) {
    const int n = lf.size[f];
    int32_t loop[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) loop[i] = p[lf.v[f][i]];
    // Canonical loop: smallest id first, then towards its smaller neighbour. The cell's
    // outward normal is the canonical one, negated when the canonical loop runs backwards.
    int m = 0;
    for (int i = 1; i < n; ++i)
      if (loop[i] < loop[m]) m = i;
    const bool forward = loop[(m + 1) % n] < loop[(m + n - 1) % n];
    int32_t can[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) can[i] = loop[forward ? (m + i) % n : (m - i + n) % n];
    // From the canonical loop, so that both owners of a face get bit-identical planes.
    Vec3 pts[4];
    for (int i = 0; i < n; ++i) pts[i] = mesh.points[can[i]];
    Vec3 nrm = newell_plane(pts, n).normal;
    if (!forward) nrm = -nrm;
    out.n[f] = nrm;
    out.o[f] = pts[0];
  }
}

}  // namespace vob
