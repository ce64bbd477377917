// Exact sides of BSP fragment vertices without constructing them (plane-based geometry, as
// in Campen and Kobbelt's exact BSP booleans). A fragment of a triangle is a convex polygon
// whose edges lie on the triangle's own edges or on splitting planes, so each vertex is
// named by the two lines it joins: a triangle vertex, a triangle edge met by a plane ("edge
// point"), or the triangle's plane met by two planes ("meet point"). Its side of another
// plane is then the sign of a fixed polynomial of the input doubles. An interval box of the
// vertex, computed once from those planes (never from earlier vertices, so its width does
// not grow with the tree's depth), decides that sign almost always; exact arithmetic on
// the doubles' mantissas (CGAL::Mpzf) decides the rest. A plane is given by three double
// points; its side of x is orient3d(p0, p1, p2, x).
//
// Internal to bsp_tree.cpp (CGAL types in the interface).
#pragma once
#include <CGAL/Interval_nt.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "harness/geometry/vec3.h"

namespace vob::xmpvo::bsp {

using IA = CGAL::Interval_nt<false>;  // needs rounding towards +inf: see RoundUp
struct IBox {
  IA x, y, z;
};

// Rounding towards +inf for the interval code in its scope, restored after. Interval
// functions below must run inside one; orient3d (round to nearest) must not.
class RoundUp {
 public:
  RoundUp();
  ~RoundUp();
  RoundUp(const RoundUp&) = delete;
  RoundUp& operator=(const RoundUp&) = delete;

 private:
  CGAL::FPU_CW_t backup_;
};

class PlaneTable {
 public:
  // Planes ever added, at most (tags fit 30 bits in FragmentOps' memo); add throws beyond.
  static constexpr int64_t kMaxTag = (int64_t{1} << 30) - 2;
  // Adds the plane through a, b, c (not collinear); returns its id (0, 1, ...).
  int32_t add(Vec3 a, Vec3 b, Vec3 c);
  int32_t size() const { return static_cast<int32_t>(pts_.size() / 3); }
  void truncate(int32_t n) {
    pts_.resize(3 * static_cast<size_t>(n)), approx_.resize(n), dbl_.resize(n), tag_.resize(n);
  }
  // A number naming the plane for good: a plane added after a truncate gets a new one.
  int64_t tag(int32_t id) const { return tag_[id]; }
  const Vec3* points(int32_t id) const { return &pts_[3 * static_cast<size_t>(id)]; }

  // Boxes (inside RoundUp). edge_point: segment pq met by plane j, p and q strictly on
  // opposite sides of j. meet_point: planes t, i, j meeting in one point.
  IBox edge_point(Vec3 p, Vec3 q, int32_t j) const;
  IBox meet_point(int32_t t, int32_t i, int32_t j) const;
  // Side of plane h at every point of the box: +1 or -1, or 2 when the box is not on one
  // open side (inside RoundUp).
  int filtered_side(int32_t h, const IBox& b) const;

  // Exact sides of the same points (round to nearest or not, exact either way).
  int exact_side_edge(Vec3 p, Vec3 q, int32_t j, int32_t h) const;
  int exact_side_meet(int32_t t, int32_t i, int32_t j, int32_t h) const;

  // Side of a double point (round to nearest) when the double normal's value clears its
  // rounding bound, else 2. The bound: Shewchuk's for orient3d's first stage, (7 + 56 eps)
  // eps times the permanent (eps = 2^-53, so 7.8e-16), which this evaluation (rounded
  // differences, 2x2 minors, three products summed) matches term for term.
  int point_side_filtered(int32_t h, Vec3 p) const {
    const DPlane& d = dbl_[h];
    const Vec3 w = p - d.a;
    const double v = d.n.x * w.x + d.n.y * w.y + d.n.z * w.z;
    const double perm = d.nabs.x * std::fabs(w.x) + d.nabs.y * std::fabs(w.y) + d.nabs.z * std::fabs(w.z);
    if (perm > 1e-250 && std::fabs(v) > 1e-15 * perm) return v > 0 ? 1 : -1;
    return 2;
  }
  // Exact side of a double point: orient3d.
  int point_side_exact(int32_t h, Vec3 p) const;
  // A guess of the side for choosing splitters, in plain doubles: 2 when the value is
  // within a relative 1e-12 of zero (unknown). Never used where exactness matters.
  int approx_side(int32_t h, Vec3 p) const {
    const DPlane& d = dbl_[h];
    const Vec3 w = p - d.a;
    const double v = d.n.x * w.x + d.n.y * w.y + d.n.z * w.z;
    const double perm = d.nabs.x * std::fabs(w.x) + d.nabs.y * std::fabs(w.y) + d.nabs.z * std::fabs(w.z);
    return v > 1e-12 * perm ? 1 : (v < -1e-12 * perm ? -1 : 2);
  }

 private:
  struct IPlane {
    IA n[3], w;  // n . x - w is the plane's side function (n = (p1-p0) x (p2-p0), w = n . p0)
  };
  // The same normal in doubles, and per component the sum of |products| that bounds its
  // rounding (the scheme of bsp_xmpvo.cpp's node_det_sign).
  struct DPlane {
    Vec3 a, n, nabs;
  };
  mutable int64_t exact_points_ = 0;

 public:
  int64_t exact_point_tests() const { return exact_points_; }

 private:
  std::vector<Vec3> pts_;
  std::vector<IPlane> approx_;  // computed under RoundUp in add()
  std::vector<DPlane> dbl_;
  std::vector<int64_t> tag_;
  int64_t added_ = 0;
};

}  // namespace vob::xmpvo::bsp
