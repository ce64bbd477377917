#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "harness/raster/cell_clip.h"
#include "harness/raster/fragments.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/splat.h"
#include "harness/scene/input_error.h"
#include "tests/support/test_meshes.h"

using namespace vob;

namespace {

// 8x8 orthographic view of the z = 0 plane where pixel (i, j) has its centre at world
// (i - 3.5, j - 3.5): every number below is exact, so centres lie exactly on edges.
Camera exact_ortho(int size = 8) {
  Camera c;
  c.eye = {0, 0, 10};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.ortho = true;
  c.ortho_height = size;
  c.width = c.height = size;
  return c;
}

using Coverage = std::vector<int>;  // per sample

void add(Coverage& cov, const SampleFrame& f, const Vec3* v, int n) {
  rasterize_polygon(f, v, n, f.bounds(), [&](int sx, int sy, double) { ++cov[f.index(sx, sy)]; });
}

// Analytic ray / triangle test (Moller-Trumbore) with the hit parameter, for comparisons.
bool ray_hits(const Ray& r, Vec3 a, Vec3 b, Vec3 c, double& t, double& margin) {
  const Vec3 e1 = b - a, e2 = c - a, p = cross(r.dir, e2);
  const double det = dot(e1, p);
  t = 0;
  margin = 0;  // parallel rays count as grazing
  if (std::fabs(det) < 1e-300) return false;
  const Vec3 s = r.origin - a;
  const double u = dot(s, p) / det;
  const Vec3 q = cross(s, e1);
  const double v = dot(r.dir, q) / det;
  t = dot(e2, q) / det;
  margin = std::min({u, v, 1 - u - v});
  return margin >= 0;
}

}  // namespace

TEST(PolygonRaster, SquareSplitIntoTwoTrianglesCoversEachCentreOnce) {
  const SampleFrame f(exact_ortho(), 1);
  const Vec3 a{-2.5, -2.5, 0}, b{2.5, -2.5, 0}, c{2.5, 2.5, 0}, d{-2.5, 2.5, 0};
  // Every vertex order and orientation of the two halves (diagonal a-c through centres).
  const std::vector<std::array<Vec3, 3>> t1s = {{a, b, c}, {c, b, a}, {b, c, a}};
  const std::vector<std::array<Vec3, 3>> t2s = {{a, c, d}, {d, c, a}, {c, d, a}};
  for (const auto& t1 : t1s)
    for (const auto& t2 : t2s) {
      Coverage cov(f.num_samples(), 0);
      add(cov, f, t1.data(), 3);
      add(cov, f, t2.data(), 3);
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
          const double x = i - 3.5, y = j - 3.5;
          // Top-left rule: the left (x = -2.5) and top (y = 2.5) edges are inside.
          const int expect = (x >= -2.5 && x < 2.5 && y > -2.5 && y <= 2.5) ? 1 : 0;
          EXPECT_EQ(cov[f.index(i, j)], expect) << "pixel " << i << "," << j;
        }
    }
}

TEST(PolygonRaster, QuadEqualsItsTwoTriangles) {
  const SampleFrame f(exact_ortho(), 1);
  const Vec3 q[4] = {{-2.5, -2.5, 0}, {2.5, -2.5, 0}, {2.5, 2.5, 0}, {-2.5, 2.5, 0}};
  Coverage cov(f.num_samples(), 0);
  add(cov, f, q, 4);
  int covered = 0;
  for (int v : cov) {
    EXPECT_LE(v, 1);
    covered += v;
  }
  EXPECT_EQ(covered, 25);
}

TEST(PolygonRaster, FanAroundACentreCoversItOnce) {
  const SampleFrame f(exact_ortho(), 1);
  const Vec3 o{0.5, 0.5, 0};  // exactly the centre of pixel (4, 4)
  const Vec3 ring[6] = {{3.5, 0.5, 0}, {2.5, 3.5, 0}, {-1.5, 2.5, 0},
                        {-2.5, 0.5, 0}, {-0.5, -2.5, 0}, {2.5, -1.5, 0}};
  Coverage cov(f.num_samples(), 0);
  for (int k = 0; k < 6; ++k) {
    // Alternate orientations: the rule must not depend on them.
    const Vec3 v[3] = {o, ring[k], ring[(k + 1) % 6]};
    const Vec3 w[3] = {ring[(k + 1) % 6], ring[k], o};
    add(cov, f, k % 2 ? v : w, 3);
  }
  EXPECT_EQ(cov[f.index(4, 4)], 1);
  for (int v : cov) EXPECT_LE(v, 1);
}

TEST(PolygonRaster, DepthIsTheRayParameterOnThePlane) {
  for (bool ortho : {true, false}) {
    Camera cam = test::test_camera({0.3, -0.2, 6}, {0, 0, 0}, 40, 30, ortho, 5.0);
    cam.up = {0, 1, 0};
    const SampleFrame f(cam, 1);
    auto z = [](double x, double y) { return 0.3 * x - 0.2 * y + 0.1; };
    const Vec3 v[3] = {{-2, -2, z(-2, -2)}, {2.5, -1.5, z(2.5, -1.5)}, {0, 2, z(0, 2)}};
    int n = 0;
    rasterize_polygon(f, v, 3, f.bounds(), [&](int sx, int sy, double t) {
      const Ray r = cam.ray(sx + 0.5, sy + 0.5);
      const Vec3 p = r.origin + r.dir * t;
      EXPECT_NEAR(p.z, z(p.x, p.y), 1e-12);
      ++n;
    });
    EXPECT_GT(n, 100);
  }
}

TEST(PolygonRaster, PerspectiveMeshIsWatertightAndMatchesRayTests) {
  // A bumpy 6x6 grid of triangles seen in perspective: every sample whose ray clearly hits
  // the surface is covered exactly once, and nothing is covered twice.
  Camera cam = test::test_camera({1.3, -4.1, 3.7}, {0.1, 0.2, 0}, 64, 48);
  const SampleFrame f(cam, 1);
  auto P = [](int i, int j) {
    const double x = -1.5 + 0.5 * i, y = -1.5 + 0.5 * j;
    return Vec3{x, y, 0.2 * std::sin(2 * x) * std::cos(3 * y)};
  };
  std::vector<std::array<Vec3, 3>> tris;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      tris.push_back({P(i, j), P(i + 1, j), P(i + 1, j + 1)});
      tris.push_back({P(i + 1, j + 1), P(i, j + 1), P(i, j)});  // same diagonal, flipped
    }
  Coverage cov(f.num_samples(), 0);
  for (const auto& t : tris) add(cov, f, t.data(), 3);
  int inside = 0;
  for (int sy = 0; sy < f.rows(); ++sy)
    for (int sx = 0; sx < f.cols(); ++sx) {
      EXPECT_LE(cov[f.index(sx, sy)], 1);
      const Ray r = cam.ray(sx + 0.5, sy + 0.5);
      int clear = 0;
      for (const auto& t : tris) {
        double th, m;
        if (ray_hits(r, t[0], t[1], t[2], th, m) && th > 0 && m > 1e-9) ++clear;
      }
      if (clear > 0) {
        ++inside;
        EXPECT_EQ(cov[f.index(sx, sy)], 1) << sx << "," << sy;
      }
    }
  EXPECT_GT(inside, 500);
}

TEST(PolygonRaster, SpansOfFourRowsInLanesMatchTheRowByRowLoop) {
  // Random triangles, large and small, some crossing the eye plane, in a perspective and an
  // orthographic frame (whose exact grid gives edges with a == 0): the AVX2 spans4 gives
  // each row the columns of the portable loop, at every row offset and clip.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  const Camera cams[] = {test::test_camera({1.3, -4.1, 3.7}, {0.1, 0.2, 0}, 64, 48), exact_ortho(16)};
  int rows = 0, nonempty = 0;
  for (const Camera& cam : cams) {
    const SampleFrame f(cam, 1);
    for (int k = 0; k < 400; ++k) {
      Vec3 v[4];
      const double scale = k % 3 == 0 ? 0.05 : 1.0;
      for (Vec3& p : v) p = {u(rng), u(rng), u(rng)};
      for (int i = 1; i < 4; ++i) v[i] = v[0] + (v[i] - v[0]) * scale;
      if (cam.ortho && k % 2) {  // axis-aligned edges on the exact grid
        v[0] = {std::round(u(rng)) + 0.5, std::round(u(rng)) + 0.5, 0};
        v[1] = v[0] + Vec3{3, 0, 0}, v[2] = v[0] + Vec3{3, 2, 0.5}, v[3] = v[0] + Vec3{0, 2, 0};
      }
      PolygonRaster p;
      if (!p.setup(f, v, k % 4 < 2 ? 3 : 4)) continue;
      const SampleRect b = p.bounds();
      for (int i = 0; i < p.triangles(); ++i)
        for (int sy = b.y0 - 3; sy <= b.y1 + 3; ++sy)
          for (const int x0 : {b.x0 - 2, b.x0 + 1}) {
            int lo[4], hi[4], plo[4], phi[4];
            p.spans4(i, sy, x0, b.x1 + 2, lo, hi);
            p.spans4(i, sy, x0, b.x1 + 2, plo, phi, true);
            for (int j = 0; j < 4; ++j) {
              ++rows;
              EXPECT_EQ(lo[j] <= hi[j], plo[j] <= phi[j]) << k << " row " << sy + j;
              if (plo[j] > phi[j]) continue;
              ++nonempty;
              EXPECT_EQ(lo[j], plo[j]) << k << " row " << sy + j;
              EXPECT_EQ(hi[j], phi[j]) << k << " row " << sy + j;
            }
          }
    }
  }
  EXPECT_GT(nonempty, 1000);
  EXPECT_GT(rows, nonempty);
}

TEST(PolygonRaster, BatchedEmitGetsTheSamplesOfTheOneByOneEmit) {
  // Both rules, polygons from a few samples up to more than one batch (kRowHitCap): the
  // batched emit sees the same samples, depths and order as emit(sx, sy, t).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (const RasterRule rule : {RasterRule::exact, RasterRule::gl}) {
    const SampleFrame f(test::test_camera({1.3, -4.1, 3.7}, {0.1, 0.2, 0}, 96, 64), 1, rule);
    size_t samples = 0, largest = 0;
    for (int k = 0; k < 200; ++k) {
      Vec3 v[4];
      const double scale = k % 4 == 0 ? 0.1 : 1.0;
      for (Vec3& p : v) p = Vec3{u(rng), u(rng), 0.3 * u(rng)} * scale;
      const int n = k % 2 ? 4 : 3;
      if (n == 4) v[2] = v[1] + v[3] - v[0];  // a parallelogram: planar and convex
      PolygonRaster p;
      if (!p.setup(f, v, n)) continue;
      std::vector<std::tuple<int, int, double>> one, batched;
      p.scan(f.bounds(), [&](int sx, int sy, double t) { one.emplace_back(sx, sy, t); });
      p.scan(f.bounds(), [&](const RowHits& h, int m) {
        EXPECT_GT(m, 0);
        EXPECT_LE(m, kRowHitCap);
        for (int j = 0; j < m; ++j) batched.emplace_back(h.sx[j], h.sy[j], h.t[j]);
      });
      EXPECT_EQ(batched, one) << k;
      samples += one.size();
      largest = std::max(largest, one.size());
    }
    EXPECT_GT(samples, 2000u);
    EXPECT_GT(largest, size_t(kRowHitCap));
  }
}

TEST(PolygonRaster, SupersampleCounts) {
  const Vec3 q[4] = {{-2.5, -2.5, 0}, {2.5, -2.5, 0}, {2.5, 2.5, 0}, {-2.5, 2.5, 0}};
  for (int S : {1, 2, 3, 4}) {
    const SampleFrame f(exact_ortho(), S);
    EXPECT_EQ(f.num_samples(), 64 * S * S);
    Coverage cov(f.num_samples(), 0);
    add(cov, f, q, 4);
    int n = 0;
    for (int v : cov) n += v;
    EXPECT_EQ(n, 25 * S * S) << "S=" << S;
  }
}

TEST(PolygonRaster, PolygonCrossingTheEyePlane) {
  // Perspective: one vertex behind the eye. Coverage must equal the analytic t > 0 hits.
  Camera cam = test::test_camera({0, 0, 0}, {0, 0, -1}, 48, 48);
  cam.up = {0, 1, 0};
  const SampleFrame f(cam, 1);
  const Vec3 v[3] = {{-3, -1, -2}, {2, -2, -4}, {0.5, 2.5, 3}};
  Coverage cov(f.num_samples(), 0);
  int n = 0;
  rasterize_polygon(f, v, 3, f.bounds(), [&](int sx, int sy, double t) {
    ++cov[f.index(sx, sy)];
    EXPECT_GT(t, 0);
    EXPECT_TRUE(std::isfinite(t));
    ++n;
  });
  for (int sy = 0; sy < f.rows(); ++sy)
    for (int sx = 0; sx < f.cols(); ++sx) {
      double t, m;
      const bool hit = ray_hits(cam.ray(sx + 0.5, sy + 0.5), v[0], v[1], v[2], t, m) && t > 0;
      if (std::fabs(m) > 1e-9) {
        EXPECT_EQ(cov[f.index(sx, sy)], hit ? 1 : 0) << sx << "," << sy;
      }
    }
  EXPECT_GT(n, 0);
  // A quad around the eye, in the eye plane (edge-on): covers nothing.
  const Vec3 q[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const Vec3 edge_on[4] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  int m = 0;
  rasterize_polygon(f, q, 4, f.bounds(), [&](int, int, double) { ++m; });
  rasterize_polygon(f, edge_on, 4, f.bounds(), [&](int, int, double) { ++m; });
  EXPECT_EQ(m, 0);
}

// project_all (four points in AVX2 lanes) against ProjectedVertex::of, bit for bit: points
// in front of, on and behind the eye plane, far off, NaN; every count 0..13 (the scalar
// tail); perspective and orthographic.
TEST(SampleFrame, ProjectAllGivesTheBitsOfProjectedVertexOf) {
  Camera persp = test::test_camera({0.3, -0.2, 7}, {0.1, 0.05, -1}, 97, 61);
  persp.up = {0.1, 1, 0};
  Camera ortho = exact_ortho(13);
  ortho.eye = {0.2, -0.1, 10};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-9, 9);
  std::vector<Vec3> pts;
  for (int i = 0; i < 200; ++i) pts.push_back({u(rng), u(rng), u(rng) * (i % 3 ? 1.0 : 1e3)});
  pts.push_back(persp.eye);                                   // zc = 0
  pts.push_back(persp.eye + Vec3{1, 1, 0});                   // zc = 0 off axis
  pts.push_back({std::nan(""), 0, 0});
  pts.push_back({1e150, -1e150, 1e150});
  int behind = 0;
  for (const Camera& cam : {persp, ortho}) {
    const SampleFrame f(cam, 1);
    for (size_t n = 0; n <= 13; ++n)
      for (size_t first = 0; first + n <= pts.size(); first += 7) {
        std::vector<ProjectedVertex> got(n);
        f.project_all(pts.data() + first, n, got.data());
        for (size_t i = 0; i < n; ++i) {
          const ProjectedVertex want = ProjectedVertex::of(f, pts[first + i]);
          EXPECT_EQ(got[i].in_front, want.in_front) << i;
          EXPECT_EQ(std::memcmp(&got[i].x, &want.x, sizeof(double)), 0) << got[i].x << " " << want.x;
          EXPECT_EQ(std::memcmp(&got[i].y, &want.y, sizeof(double)), 0) << got[i].y << " " << want.y;
          behind += !want.in_front;
        }
      }
  }
  EXPECT_GT(behind, 50);
}

TEST(PolygonRaster, RejectsOtherVertexCounts) {
  const SampleFrame f(exact_ortho(), 1);
  const Vec3 v[5] = {};
  PolygonRaster p;
  EXPECT_THROW(p.setup(f, v, 5), InputError);
  EXPECT_THROW(SampleFrame(exact_ortho(), 0), InputError);
}

TEST(CellClip, NeighbourSegmentsMeetExactly) {
  const CellMesh m = test::kuhn_block(2, 1.0, 0.15, 7);
  validate_cell_mesh(m, "test");
  for (bool ortho : {false, true}) {
    const Camera cam = test::test_camera({5.1, -3.3, 4.2}, {1, 1, 1}, 48, 48, ortho, 4.0);
    const Scene s = Scene::from_mesh("block", m);
    const FragmentLists fl = collect_fragments(s, cam, all_primitives(s));
    int64_t joins = 0, pairs = 0, frags = 0;
    for (int64_t i = 0; i < fl.num_samples(); ++i) {
      std::vector<Fragment> v(fl.local(i).begin(), fl.local(i).end());
      for (size_t k = 1; k < v.size(); ++k) EXPECT_LT(v[k - 1].pos, v[k].pos);  // drawing order
      std::sort(v.begin(), v.end(), [](auto& a, auto& b) { return a.t_in < b.t_in; });
      frags += int64_t(v.size());
      for (size_t k = 1; k < v.size(); ++k) {
        EXPECT_LE(v[k - 1].t_out, v[k].t_in);  // never overlap
        joins += v[k - 1].t_out == v[k].t_in;
        ++pairs;
      }
    }
    // Inside a convex block consecutive segments share a face: they meet bit-exactly,
    // except where a ray passes an edge and drops a negligible segment.
    EXPECT_GT(frags, 1000);
    EXPECT_GE(joins, pairs * 99 / 100);
  }
}

TEST(CellClip, SegmentsMatchAnalyticTetIntersection) {
  CellMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  validate_cell_mesh(m, "tet");
  const Scene s = Scene::from_mesh("tet", m);
  const int faces[4][3] = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}};
  for (bool ortho : {false, true}) {
    const Camera cam = test::test_camera({2.2, 1.7, 1.4}, {0.25, 0.25, 0.25}, 40, 40, ortho, 1.6);
    const FragmentLists fl = collect_fragments(s, cam, {0});
    int checked = 0;
    for (int sy = 0; sy < 40; ++sy)
      for (int sx = 0; sx < 40; ++sx) {
        const Ray r = cam.ray(sx + 0.5, sy + 0.5);
        std::vector<double> ts;
        double margin = 1;
        for (const auto& fc : faces) {
          double t, mg;
          if (ray_hits(r, m.points[fc[0]], m.points[fc[1]], m.points[fc[2]], t, mg)) ts.push_back(t);
          margin = std::min(margin, std::fabs(mg));
        }
        if (margin < 1e-9) continue;  // grazing an edge
        const auto fr = fl.at(sx, sy);
        ASSERT_EQ(fr.size(), ts.size() == 2 ? 1u : 0u);
        if (ts.size() == 2) {
          EXPECT_NEAR(fr[0].t_in, std::min(ts[0], ts[1]), 1e-12);
          EXPECT_NEAR(fr[0].t_out, std::max(ts[0], ts[1]), 1e-12);
          ++checked;
        }
      }
    EXPECT_GT(checked, 50);
  }
}

TEST(CellClip, EyeInsideACellGivesSegmentsFromZero) {
  const CellMesh m = test::kuhn_block(1, 2.0);
  const Scene s = Scene::from_mesh("cube", m);
  Camera cam = test::test_camera({1.2, 0.9, 0.7}, {0.3, 1.5, 1.1}, 32, 32);
  const FragmentLists fl = collect_fragments(s, cam, all_primitives(s));
  for (int64_t i = 0; i < fl.num_samples(); ++i) {
    const auto fr = fl.local(i);
    ASSERT_GE(fr.size(), 1u);  // the eye is inside the block: every ray sees it
    double first = 1e300;
    for (const Fragment& x : fr) first = std::min(first, x.t_in);
    EXPECT_EQ(first, 0.0);
  }
}

TEST(Splat, FootprintIsADisc) {
  VoxelGrid g;
  g.dims = {1, 1, 1};
  g.values = {1.0f};
  g.threshold = 0.5f;
  const Scene s = Scene::from_grid("one", g);
  Camera cam = test::test_camera({0, 0, 10}, {0, 0, 0}, 64, 64, true, 8.0);
  cam.up = {0, 1, 0};
  for (int S : {1, 2}) {
    CollectOptions o;
    o.supersample = S;
    o.splat_radius_px = 10;
    const FragmentLists fl = collect_fragments(s, cam, {0}, o);
    const double area = double(fl.fragments.size()) / (S * S);
    EXPECT_NEAR(area, M_PI * 100, 0.05 * M_PI * 100);
    for (const Fragment& fr : fl.fragments) EXPECT_DOUBLE_EQ(fr.t_in, 10.0);
  }
  // Automatic radius: the half diagonal sqrt(3)/2 voxel at 8 pixels per unit.
  Splat sp;
  const SampleFrame f(cam, 1);
  ASSERT_TRUE(make_splat(f, {0, 0, 0}, {1, 1, 1}, 0, sp));
  EXPECT_NEAR(sp.radius, 8 * std::sqrt(3.0) / 2, 1e-12);
}

// The gl rule's snap refuses, with one clear error, window coordinates beyond the range it
// describes (a vertex next to the eye plane used to overflow the edge functions: UBSan on
// eye-inside), and takes every coordinate within it.
TEST(GlSnap, RefusesCoordinatesBeyondItsRange) {
  EXPECT_EQ(gl_snap(0.5), 0);
  EXPECT_EQ(gl_snap(0.5 + kGlMaxWindow - 1), int64_t(kGlMaxWindow - 1) * kGlSubpixels);
  EXPECT_EQ(gl_snap(0.5 - kGlMaxWindow + 1), -int64_t(kGlMaxWindow - 1) * kGlSubpixels);
  EXPECT_THROW(gl_snap(0.5 + kGlMaxWindow), InputError);
  EXPECT_THROW(gl_snap(-2.8e17), InputError);
  EXPECT_THROW(gl_snap(std::nan("")), InputError);
  EXPECT_THROW(gl_snap(HUGE_VAL), InputError);
}
