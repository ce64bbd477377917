// The hard cases really are hard: cycles are cycles, eyes lie in planes or inside, faces
// are edge-on, and every supplied camera is valid.
#include <cmath>

#include "harness/geometry/predicates.h"
#include "harness/scene/mesh_faces.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
std::vector<Camera> views_of(const std::string& name, const Scene& s) {
  const DatasetInfo& info = find_dataset(name);
  EXPECT_TRUE(info.views) << name << " supplies no views";
  return info.views ? info.views(s, 512, 512) : std::vector<Camera>{};
}

// MPVO arrows from `eye_side(face)` (> 0: the eye is on the positive side of the face's
// plane, so cell0 is behind cell1 and must be drawn first). Returns successor lists.
template <class Side>
std::vector<std::vector<int>> arrows(const Scene& s, Side eye_side) {
  const MeshFaces& f = s.faces();
  const FacePlanes& pl = s.face_planes();
  std::vector<std::vector<int>> next(s.mesh().num_cells());
  for (size_t i = 0; i < f.num_faces(); ++i) {
    if (f.cell1[i] < 0) continue;
    const double side = eye_side(pl.normal[i], pl.offset[i]);
    EXPECT_NE(side, 0.0) << "eye in the plane of face " << i;
    if (side > 0)
      next[f.cell0[i]].push_back(f.cell1[i]);
    else
      next[f.cell1[i]].push_back(f.cell0[i]);
  }
  return next;
}

// Length of the directed cycle through cell 0 when every cell has exactly one successor.
int cycle_length(const std::vector<std::vector<int>>& next) {
  int c = 0, steps = 0;
  do {
    if (next[c].size() != 1) return -1;
    c = next[c][0];
    ++steps;
  } while (c != 0 && steps <= static_cast<int>(next.size()));
  return c == 0 ? steps : -1;
}

// Parameter interval [t0, t1] of the ray inside a convex cell with planar faces.
bool clip(const CellMesh& m, int cell, const Ray& r, double& t0, double& t1) {
  t0 = 0;
  t1 = 1e300;
  const LocalFaces& lf = cell_local_faces(m.types[cell]);
  const int32_t* p = m.cell_points(cell);
  for (int f = 0; f < lf.count; ++f) {
    const Vec3 a = m.points[p[lf.v[f][0]]];
    const Vec3 n = cross(m.points[p[lf.v[f][1]]] - a, m.points[p[lf.v[f][2]]] - a);  // outward
    const double num = -dot(n, r.origin - a), den = dot(n, r.dir);
    if (den == 0) {
      if (num < 0) return false;
    } else if (den > 0) {
      t1 = std::min(t1, num / den);
    } else {
      t0 = std::max(t0, num / den);
    }
  }
  return t0 < t1;
}
}  // namespace

TEST(HardCases, CycleArrowsFormOneDirectedCycle) {
  for (int cells : {6, 7, 12, 64}) {
    const Scene s = make("cycle", {{"cells", std::to_string(cells)}});
    const auto cams = views_of("cycle", s);
    ASSERT_EQ(cams.size(), 2u);
    for (const Camera& cam : cams) {
      cam.validate();
      const Vec3 eye = cam.eye, dir = cam.forward();
      const auto next = cam.ortho
                            ? arrows(s, [&](Vec3 n, double) { return -dot(n, dir); })
                            : arrows(s, [&](Vec3 n, double d) { return dot(n, eye) + d; });
      EXPECT_EQ(cycle_length(next), cells) << "view " << (cam.ortho ? "ortho" : "perspective");
    }
    // From below the ring the cycle runs the other way round, but is still a cycle.
    const auto below = arrows(s, [&](Vec3 n, double d) { return dot(n, Vec3{0, 0, -5}) + d; });
    EXPECT_EQ(cycle_length(below), cells);
  }
}

TEST(HardCases, CycleRaysCrossTheSeparatingFaces) {
  // A real visibility cycle: some pixel ray passes from cell i+1 into cell i for every i.
  const Scene s = make("cycle");
  const Camera cam = views_of("cycle", s)[0];
  const CellMesh& m = s.mesh();
  std::vector<bool> seen(m.num_cells(), false);
  for (int j = 0; j < 512; j += 4)
    for (int i = 0; i < 512; i += 4) {
      const Ray r = cam.pixel_ray(i, j);
      for (size_t c = 0; c < m.num_cells(); ++c) {
        const size_t n = (c + 1) % m.num_cells();
        double a0, a1, b0, b1;
        if (clip(m, int(c), r, a0, a1) && clip(m, int(n), r, b0, b1) && b1 <= a0 + 1e-9 &&
            a1 - a0 > 1e-6 && b1 - b0 > 1e-6)
          seen[c] = true;  // cell c+1 in front of cell c along this ray
      }
    }
  for (size_t c = 0; c < m.num_cells(); ++c) EXPECT_TRUE(seen[c]) << "pair " << c;
}

TEST(HardCases, ThreeSticksOccludeEachOtherInACycle) {
  const Scene s = make("cycle-sticks");
  const CellMesh& m = s.mesh();
  ASSERT_EQ(m.num_cells(), 3u);
  const Camera cam = views_of("cycle-sticks", s)[0];
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 3; ++i) {
    // Where sides i and i+1 of the triangle cross (radius 2 at angle 120 i + 60 degrees).
    const double a = 2 * pi * i / 3 + pi / 3;
    const Vec3 cross_pt{2 * std::cos(a), 2 * std::sin(a), 0};
    const Ray r{cam.eye, normalize(cross_pt - cam.eye)};
    double a0, a1, b0, b1;
    ASSERT_TRUE(clip(m, i, r, a0, a1)) << i;
    ASSERT_TRUE(clip(m, (i + 1) % 3, r, b0, b1)) << i;
    EXPECT_LT(a1, b0) << "stick " << i << " must lie in front of stick " << (i + 1) % 3;
  }
}

TEST(HardCases, EyeInPlaneEyesLieInFacePlanes) {
  for (const char* n : {"4", "6", "9"}) {
    const Scene s = make("eye-in-plane", {{"n", n}});
    const CellMesh& m = s.mesh();
    const MeshFaces& f = s.faces();
    for (const Camera& cam : views_of("eye-in-plane", s)) {
      cam.validate();
      int on = 0;
      for (size_t i = 0; i < f.num_faces(); ++i) {
        const int32_t* v = f.face_points(i);
        on += orient3d(m.points[v[0]], m.points[v[1]], m.points[v[2]], cam.eye) == 0;
      }
      EXPECT_GT(on, 10) << "n=" << n << " eye " << cam.eye.x << "," << cam.eye.y << "," << cam.eye.z;
    }
  }
}

TEST(HardCases, EdgeOnViewsLookAlongFacePlanes) {
  const Scene s = make("edge-on", {{"n", "4"}});
  const CellMesh& m = s.mesh();
  const MeshFaces& f = s.faces();
  const auto cams = views_of("edge-on", s);
  ASSERT_EQ(cams.size(), 4u);
  for (const Camera& cam : cams) {
    cam.validate();
    EXPECT_TRUE(cam.ortho);
    int edge_on = 0;
    for (size_t i = 0; i < f.num_faces(); ++i) {
      const int32_t* v = f.face_points(i);
      edge_on += orient_direction(m.points[v[0]], m.points[v[1]], m.points[v[2]], cam.forward()) == 0;
    }
    EXPECT_GT(edge_on, int(f.num_faces()) / 3);
  }
  // The shifted view samples exactly on the grid lines x = 0..n.
  const Camera& shifted = cams[1];
  int on_lines = 0;
  for (int i = 0; i < shifted.width; ++i) {
    const double x = shifted.pixel_ray(i, 0).origin.x;
    on_lines += x >= 0 && x <= 4 && x == std::floor(x);
  }
  EXPECT_EQ(on_lines, 5);
}

TEST(HardCases, EyeInsideEyesAreInsideTheBlock) {
  const Scene s = make("eye-inside");
  const Aabb b = s.bounds();
  const auto cams = views_of("eye-inside", s);
  ASSERT_EQ(cams.size(), 2u);
  for (const Camera& cam : cams) {
    cam.validate();
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(cam.eye[a], b.lo[a]);
      EXPECT_LT(cam.eye[a], b.hi[a]);
    }
  }
  const auto& pts = s.mesh().points;
  EXPECT_NE(std::find(pts.begin(), pts.end(), cams[1].eye), pts.end()) << "eye at a mesh vertex";
}

TEST(HardCases, ViewsFollowTheRequestedImageSize) {
  for (const auto& info : dataset_registry()) {
    if (!info.views) continue;
    const Scene s = make(info.name);
    for (const Camera& c : info.views(s, 300, 200)) {
      EXPECT_EQ(c.width, 300) << info.name;
      EXPECT_EQ(c.height, 200) << info.name;
      EXPECT_NO_THROW(c.validate()) << info.name;
    }
  }
}
