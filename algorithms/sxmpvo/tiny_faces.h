// SXMPVO phase III's path for exterior faces that cover a few samples: most faces of a fine
// mesh cover none or one or two pixel centres, and the general rasterizer
// (harness/raster/polygon_raster.h) pays for them with a facing test per triangle, a
// candidate box widened by a sample on each side and a division per edge per row.
//
// Here a triangle whose vertices all lie in front of the eye is scanned over the sample
// centres of its projected box only (the box PolygonRaster already trusts to reject faces
// that cover no centre), with its facing sign taken from MPVO's phase I (a triangle's
// phase-I sign is the exact sign of orient3d of its three points, the same predicate the
// rasterizer evaluates) and its projected points computed once per view. Each decision is
// made by PolygonRaster's own expressions, evaluated in the same order: the edge functions
// of the ray from the canonical edge direction, the top-left rule for exact zeros, and the
// same row kernel (harness/raster/row_coverage.h) for coverage and t = num / (n . X) * |X|.
// So a sample in the box is covered here exactly when it is covered there, and t is the
// same double. Outside the box
// the rasterizer (whose candidates reach one sample further) can only add rounding noise of
// a triangle seen edge-on, rays that graze it; the oracle's cell clipping drops those too
// (tests/algorithms/sxmpvo/tiny_faces_test.cpp).
#pragma once
#include <cmath>
#include <cstdint>

#include "algorithms/sxmpvo/abuffer.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/row_coverage.h"
#include "harness/raster/sample_frame.h"

namespace vob::sxmpvo {

// Largest projected box, in samples, that the tiny path scans sample by sample; a larger
// face goes to PolygonRaster, whose spans skip the box's empty corners.
constexpr int kTinyMaxSamples = 64;

enum class BoxKind { None, Tiny, Large };

// The sample centres of a polygon's projected box (PolygonRaster::may_cover_a_sample's
// tightened box, same margin), clipped to the frame. None: no sample centre can be covered;
// Tiny: `box` holds at most kTinyMaxSamples samples; Large: anything else, including a
// vertex not in front of the eye (then the projection bounds nothing).
BoxKind sample_box(const SampleFrame& frame, const ProjectedVertex* q, int n, SampleRect& box);
// The same for the polygon whose vertex i is all[ids[i]] (no copy of its vertices).
BoxKind sample_box(const SampleFrame& frame, const ProjectedVertex* all, const int32_t* ids, int n,
                   SampleRect& box);

// Scans the triangle v[0..3) over `box` (from sample_box, every vertex in front of the eye)
// and calls emit(sx, sy, t) for each covered sample. `phase1_sign` is MpvoCore's sign of
// the face whose first three points are v[0], v[1], v[2] (+1: the eye on the side its
// right-hand normal points to); it must not be 0.
template <class Emit>
void scan_tiny_triangle(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box,
                        Emit&& emit);

// scan_tiny_triangle's samples written straight as A-buffer entries (t, and the key of the
// sample's pixel and the face's `slot` in the batch), in the same order, to dst; returns
// their number. The lane kernels write a whole step's entries (four in AVX2, eight in
// AVX-512) whatever their coverage (no jump per sample or per hit): dst needs
// kTinyEntrySlots.
constexpr int kTinyEntrySlots = kTinyMaxSamples + 8;
using TinyEntriesFn = int (*)(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box,
                              int32_t slot, ABuffer::RawBatch::Out dst);
TinyEntriesFn tiny_entries();           // the widest kernel this CPU runs: AVX-512, AVX2, else the scalar loop
TinyEntriesFn tiny_entries_baseline();  // through scan_tiny_triangle (tests compare the kernels to it)
TinyEntriesFn tiny_entries_avx2();      // the AVX2 kernel alone; nullptr without AVX2
TinyEntriesFn tiny_entries_avx512();    // the AVX-512 kernel alone; nullptr without AVX-512 F/VL/DQ

// The triangle's edges and depth plane as the rasterizer would set them up (false: seen
// edge-on in an orthographic view, it covers no sample).
inline bool tiny_triangle_rows(const SampleFrame& fr, const Vec3* v, int phase1_sign, RowEdges& e,
                               RowDepth& depth);
// The same with the three edges in AVX2 lanes (call only when cpu_has_avx2()):
// the same bits in e[0..3) and depth (tests compare the two).
bool tiny_triangle_rows_avx2(const SampleFrame& fr, const Vec3* v, int phase1_sign, RowEdges& e, RowDepth& depth);

// ---- implementation ----

namespace detail {
// PolygonRaster::triangle_edges's ownership of an exactly zero edge value (top-left rule),
// without jumps: the sign of a is a coin toss per edge.
inline bool owns_zero(const SampleFrame& fr, const Vec3& m) {
  const double a = dot(m, fr.affine_dx()), b = dot(m, fr.affine_dy()), c = dot(m, fr.forward());
  return (a > 0) | ((a == 0) & ((b < 0) | ((b == 0) & (c > 0))));
}
// lex_less without branches: its outcome is a coin toss per edge, a mispredicted jump.
inline bool lex_less_flat(const Vec3& a, const Vec3& b) {
  return (a.x < b.x) | ((a.x == b.x) & ((a.y < b.y) | ((a.y == b.y) & (a.z < b.z))));
}
// The triangle's depth plane as the rasterizer sets it up (false: seen edge-on in an
// orthographic view).
inline bool depth_plane(const SampleFrame& fr, const Vec3* v, RowDepth& depth) {
  depth.n = cross(v[1] - v[0], v[2] - v[0]);
  depth.d = -dot(depth.n, v[0]);
  if (fr.ortho()) {
    const double nf = dot(depth.n, fr.forward());
    if (nf == 0) return false;
    depth.inv_nf = 1.0 / nf;
  } else {
    depth.num = -dot(depth.n, fr.eye() - v[0]);
  }
  return true;
}
}  // namespace detail

inline bool tiny_triangle_rows(const SampleFrame& fr, const Vec3* v, int phase1_sign, RowEdges& e, RowDepth& depth) {
  if (!detail::depth_plane(fr, v, depth)) return false;
  const bool ortho = fr.ortho();
  // The rasterizer's facing is sigma (orthographic) or -sigma (perspective), sigma being
  // orient3d(v0, v1, v2, eye), resp. orient_direction(v0, v1, v2, f) = -(phase-I sign):
  // both are -(phase-I sign).
  const double facing = -phase1_sign;
  for (int i = 0; i < 3; ++i) {
    const Vec3* ends[2] = {&v[(i + 1) % 3], &v[i]};  // fwd: pa = v[i]
    const bool fwd = detail::lex_less_flat(v[i], v[(i + 1) % 3]);
    const Vec3 &pa = *ends[fwd], &pb = *ends[!fwd];
    Vec3 m;
    double c = 0;
    if (ortho) {
      const Vec3 mp = cross(pb - pa, fr.forward());
      c = dot(mp, pa);
      m = -mp;
    } else {
      m = cross(pa - fr.eye(), pb - pa);
    }
    const double s = fwd ? facing : -facing;
    m = m * s;
    e.mx[i] = m.x, e.my[i] = m.y, e.mz[i] = m.z, e.c[i] = c * s;
    e.own[i] = detail::owns_zero(fr, m);
  }
  return true;
}

template <class Emit>
void scan_tiny_triangle(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box,
                        Emit&& emit) {
  RowEdges e;
  RowDepth depth;
  if (!tiny_triangle_rows(fr, v, phase1_sign, e, depth)) return;
  RowScanner rows(row_coverage(), fr, e, depth);
  for (int sy = box.y0; sy <= box.y1; ++sy) rows.add(sy, box.x0, box.x1, emit);
  rows.flush(emit);
}

}  // namespace vob::sxmpvo
