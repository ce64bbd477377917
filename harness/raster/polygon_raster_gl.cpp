// The gl sampling rule's coverage (raster_rule.h): llvmpipe's triangle setup
// (lp_setup_tri.c: calc_fixed_position, do_triangle_ccw) on the snapped window
// coordinates, in exact 64-bit integers.
#include <algorithm>
#include <utility>

#include "harness/raster/polygon_raster.h"

namespace vob {

bool PolygonRaster::setup_gl(const SampleFrame& frame, const Vec3* v, int n,
                             const ProjectedVertex* projected) {
  int64_t x[4], y[4];
  double q[4];  // what window depth is affine in: 1 / view depth (orthographic: view depth)
  float z[4] = {0, 0, 0, 0};  // llvmpipe's float window z, with GL's depth range
  const GlDepthRange* range = frame.gl_range();
  for (int i = 0; i < n; ++i) {
    const ProjectedVertex p = projected ? projected[i] : ProjectedVertex::of(frame, v[i]);
    if (!p.in_front) return false;  // GL clips at the near plane; the rule needs every vertex in front
    x[i] = gl_snap(p.x);
    y[i] = gl_snap(p.y);
    const double zc = dot(v[i] - frame.eye(), frame.forward());
    q[i] = frame.ortho() ? zc : 1.0 / zc;
    if (range) z[i] = llvmpipe_window_z(gl_window_depth(frame.camera(), *range, zc));
  }
  if (n == 3) {
    add_gl_triangle(x, y, q, range ? z : nullptr);
  } else {  // the harness' split, which the GL backends draw too
    int m = 0;
    for (int i = 1; i < 4; ++i)
      if (lex_less(v[i], v[m])) m = i;
    const int a = m, b = (m + 1) % 4, c = (m + 2) % 4, d = (m + 3) % 4;
    const int64_t x0[3] = {x[a], x[b], x[c]}, y0[3] = {y[a], y[b], y[c]};
    const int64_t x1[3] = {x[a], x[c], x[d]}, y1[3] = {y[a], y[c], y[d]};
    const double q0[3] = {q[a], q[b], q[c]}, q1[3] = {q[a], q[c], q[d]};
    const float z0[3] = {z[a], z[b], z[c]}, z1[3] = {z[a], z[c], z[d]};
    add_gl_triangle(x0, y0, q0, range ? z0 : nullptr);
    add_gl_triangle(x1, y1, q1, range ? z1 : nullptr);
  }
  return count_ > 0;
}

bool PolygonRaster::add_gl_triangle(const int64_t* xin, const int64_t* yin, const double* qin,
                                    const float* zin) {
  int64_t x[3] = {xin[0], xin[1], xin[2]}, y[3] = {yin[0], yin[1], yin[2]};
  double q[3] = {qin[0], qin[1], qin[2]};
  float z[3] = {0, 0, 0};
  if (zin) z[0] = zin[0], z[1] = zin[1], z[2] = zin[2];
  const int64_t area = (x[0] - x[1]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[0] - y[1]);
  if (area == 0) return false;  // llvmpipe culls zero-area triangles
  if (area < 0)  // as triangle_both does: its setup then gets the vertices as v1, v0, v2
    std::swap(x[0], x[1]), std::swap(y[0], y[1]), std::swap(q[0], q[1]), std::swap(z[0], z[1]);
  GlTriangle& t = gl_tri_[count_];
  t.has_z = zin != nullptr;
  if (t.has_z) {  // llvmpipe's own plane, from the float window positions it is handed
    const float fx[3] = {float(gl_unsnap(x[0])), float(gl_unsnap(x[1])), float(gl_unsnap(x[2]))};
    const float fy[3] = {float(gl_unsnap(y[0])), float(gl_unsnap(y[1])), float(gl_unsnap(y[2]))};
    t.zplane = llvmpipe_depth_plane(fx, fy, z);
  }
  // The depth plane through the snapped vertices.
  const double ex1 = double(x[1] - x[0]), ey1 = double(y[1] - y[0]);
  const double ex2 = double(x[2] - x[0]), ey2 = double(y[2] - y[0]);
  const double det = ex1 * ey2 - ex2 * ey1, d1 = q[1] - q[0], d2 = q[2] - q[0];
  t.x0 = x[0], t.y0 = y[0], t.q0 = q[0];
  t.qx = (d1 * ey2 - d2 * ey1) / det;
  t.qy = (d2 * ex1 - d1 * ex2) / det;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    t.dcdx[i] = y[i] - y[j];
    t.dcdy[i] = x[i] - x[j];
    // Covered when E > 0; on the edge (E == 0) too when the fill rule owns it, folded in as
    // llvmpipe does (c + 1, then a test of c - 1 >= 0).
    t.c[i] = t.dcdx[i] * x[i] - t.dcdy[i] * y[i];
    if (t.dcdx[i] < 0 || (t.dcdx[i] == 0 && t.dcdy[i] > 0)) ++t.c[i];
  }
  // llvmpipe's bounding box (bottom_edge_rule 0): pixels [min >> 8, (max - 1) >> 8].
  const int64_t lx = std::min({x[0], x[1], x[2]}), hx = std::max({x[0], x[1], x[2]});
  const int64_t ly = std::min({y[0], y[1], y[2]}), hy = std::max({y[0], y[1], y[2]});
  auto pix = [](int64_t f) { return int(std::clamp<int64_t>(f >> kGlSubpixelBits, -(1 << 30), 1 << 30)); };
  t.box = SampleRect{pix(lx), pix(ly), pix(hx - 1), pix(hy - 1)}.intersect(frame_->bounds());
  if (t.box.empty()) return false;
  ++count_;
  return true;
}

}  // namespace vob
