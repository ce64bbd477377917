// SXMPVO's tiny-face path against the shared rasterizer: for small triangles in front of
// the eye, the same samples with bit-identical depths, including samples exactly on edges
// and vertices (triangles whose corners lie on sample rays, fans around a shared vertex).
// The one difference allowed: a triangle degenerate in projection (edge-on up to rounding)
// gets rounding-noise samples from the rasterizer outside its projected box, which the
// tiny path does not scan (the oracle's cell clipping drops such grazing rays too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <tuple>
#include <vector>

#include "algorithms/sxmpvo/tiny_faces.h"
#include "harness/cpu_features.h"
#include "harness/geometry/predicates.h"

using namespace vob;
using Hits = std::vector<std::tuple<int, int, double>>;

namespace {

// MpvoCore's phase-I sign of a triangle face (v0, v1, v2).
int phase1_sign(const SampleFrame& f, const Vec3* v) {
  return f.ortho() ? -orient_direction(v[0], v[1], v[2], f.forward()) : orient3d(v[0], v[1], v[2], f.eye());
}

Hits by_raster(const SampleFrame& f, const Vec3* v) {
  Hits h;
  rasterize_polygon(f, v, 3, f.bounds(), [&](int x, int y, double t) { h.emplace_back(x, y, t); });
  std::sort(h.begin(), h.end());
  return h;
}

// The tiny path; `taken` says whether sample_box sent the triangle there, `box` where.
Hits by_tiny_path(const SampleFrame& f, const Vec3* v, bool& taken, SampleRect& box) {
  Hits h;
  ProjectedVertex q[3];
  for (int i = 0; i < 3; ++i) q[i] = ProjectedVertex::of(f, v[i]);
  const sxmpvo::BoxKind kind = sxmpvo::sample_box(f, q, 3, box);
  {  // the form SXMPVO calls, vertices by index into all projected points: the same box
    const ProjectedVertex all[4] = {ProjectedVertex{}, q[2], q[0], q[1]};
    const int32_t ids[3] = {2, 3, 1};
    SampleRect by_ids{-7, -7, -7, -7};
    EXPECT_EQ(sxmpvo::sample_box(f, all, ids, 3, by_ids), kind);
    if (kind == sxmpvo::BoxKind::Tiny) {  // (a Large box may be unset: a vertex behind the eye)
      EXPECT_TRUE(by_ids.x0 == box.x0 && by_ids.y0 == box.y0 && by_ids.x1 == box.x1 && by_ids.y1 == box.y1);
    }
  }
  taken = kind == sxmpvo::BoxKind::Tiny;
  const int s = phase1_sign(f, v);
  if (taken && s != 0) {
    sxmpvo::scan_tiny_triangle(f, v, s, box, [&](int x, int y, double t) { h.emplace_back(x, y, t); });
    // SXMPVO's entries (every kernel this CPU can run: AVX-512, AVX2, the scalar loop; SXMPVO
    // takes the first): the same samples,
    // in scan order, with the same t bits, item, pixel and rank.
    for (const sxmpvo::TinyEntriesFn fn : {sxmpvo::tiny_entries_avx512(), sxmpvo::tiny_entries_avx2(),
                                           sxmpvo::tiny_entries_baseline()}) {
      if (!fn) continue;  // a kernel this CPU cannot run
      sxmpvo::ABuffer::RawBatch columns;
      columns.reserve_more(sxmpvo::kTinyEntrySlots);
      const int n = fn(f, v, s, box, columns.add_face(17, 5), columns.at(0));
      EXPECT_EQ(n, static_cast<int>(h.size()));
      for (int j = 0; j < n && j < static_cast<int>(h.size()); ++j) {
        const auto [x, y, t] = h[j];
        const sxmpvo::ABuffer::Raw e = columns[static_cast<size_t>(j)];
        EXPECT_EQ(e.pixel, y * f.cols() + x);
        EXPECT_EQ(std::memcmp(&e.t, &t, sizeof t), 0) << e.t << " " << t;
        EXPECT_EQ(e.item, 17);
        EXPECT_EQ(e.rank, 5);
      }
    }
  }
  std::sort(h.begin(), h.end());
  return h;
}

// A point on the ray of sample-centre-ish window position (wx, wy) at ray parameter s.
Vec3 on_ray(const SampleFrame& f, const Camera& cam, double wx, double wy, double s) {
  const Ray r = cam.ray(wx, wy);
  return r.origin + r.dir * s;
}

void compare_many(const Camera& cam, bool on_centres) {
  const SampleFrame f(cam, 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int tiny = 0, covering = 0, degenerate = 0;
  for (int k = 0; k < 4000; ++k) {
    const double cx = 20 + 80 * u(rng), cy = 20 + 60 * u(rng), depth = 3 + u(rng);
    Vec3 v[3];
    for (int i = 0; i < 3; ++i) {
      double wx = cx + 4 * u(rng) - 2, wy = cy + 4 * u(rng) - 2;
      if (on_centres) wx = std::floor(wx) + 0.5, wy = std::floor(wy) + 0.5;
      v[i] = on_ray(f, cam, wx, wy, depth + 0.3 * u(rng));
    }
    bool taken = false;
    SampleRect box;
    const Hits tiny_hits = by_tiny_path(f, v, taken, box);
    if (!taken) continue;
    ++tiny;
    covering += !tiny_hits.empty();
    Hits in_box, outside;
    for (const auto& h : by_raster(f, v)) {
      const auto [x, y, t] = h;
      (x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1 ? in_box : outside).push_back(h);
    }
    ASSERT_EQ(tiny_hits, in_box) << "triangle " << k;
    if (!outside.empty()) {  // only rounding noise of a triangle seen edge-on
      ProjectedVertex q[3];
      for (int i = 0; i < 3; ++i) q[i] = ProjectedVertex::of(f, v[i]);
      const double area2 = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
      EXPECT_LT(std::fabs(area2), 1e-9) << "triangle " << k;
      ++degenerate;
    }
  }
  EXPECT_GT(tiny, 3000);
  EXPECT_GT(covering, 1000);
  if (!on_centres) {
    EXPECT_EQ(degenerate, 0);
  }
}

// Triangles around a vertex on a sample ray, with spokes along sample rows and columns:
// samples on shared edges and at the shared vertex decided alike on both paths.
void compare_fan(const Camera& cam) {
  const SampleFrame f(cam, 1);
  const Vec3 centre = on_ray(f, cam, 50.5, 40.5, 4.0);
  Vec3 rim[6];
  for (int i = 0; i < 6; ++i)
    rim[i] = on_ray(f, cam, 50.5 + 2 * std::cos(i * 1.0471975511965976),
                    40.5 + 2 * std::sin(i * 1.0471975511965976), 4.0 + 0.1 * i);
  const Vec3 axis[4] = {on_ray(f, cam, 52.5, 40.5, 4.0), on_ray(f, cam, 50.5, 42.5, 4.1),
                        on_ray(f, cam, 48.5, 40.5, 4.2), on_ray(f, cam, 50.5, 38.5, 4.3)};
  size_t hits = 0;
  for (int fan = 0; fan < 2; ++fan) {
    const int n = fan ? 4 : 6;
    for (int i = 0; i < n; ++i) {
      const Vec3 v[3] = {centre, fan ? axis[i] : rim[i], fan ? axis[(i + 1) % 4] : rim[(i + 1) % 6]};
      bool taken = false;
      SampleRect box;
      const Hits h = by_tiny_path(f, v, taken, box);
      EXPECT_TRUE(taken);
      EXPECT_EQ(h, by_raster(f, v));
      hits += h.size();
    }
  }
  EXPECT_GT(hits, 10u);
}

Camera camera(bool ortho) {
  Camera c;
  c.eye = {0.3, -0.2, 9};
  c.target = {0.1, 0.2, 0};
  c.ortho = ortho;
  c.ortho_height = 3.0;
  c.width = 120;
  c.height = 100;
  return c;
}

}  // namespace

TEST(TinyFaces, SameSamplesAndDepthsAsTheRasterizer) {
  for (bool ortho : {false, true})
    for (bool on_centres : {false, true}) compare_many(camera(ortho), on_centres);
}

TEST(TinyFaces, FanAroundASampleVertexDecidedAlike) {
  for (bool ortho : {false, true}) compare_fan(camera(ortho));
}

// Boxes of every shape the tiny path takes, 1 to 12 samples wide and high, also cut by the
// frame's right and bottom edges (AVX2 steps past the last column, masked): each kernel
// gives the rasterizer's samples, in scan order, with the same t bits.
TEST(TinyFaces, EveryBoxShapeAlike) {
  for (bool ortho : {false, true}) {
    const Camera cam = camera(ortho);
    const SampleFrame f(cam, 1);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int one_step = 0, more_steps = 0, cut = 0;
    for (int wide = 1; wide <= 12; ++wide)
      for (int high = 1; high <= 12; ++high)
        for (int k = 0; k < 6; ++k) {
          // k 0-3 inside the frame, 4 over its right edge, 5 over its bottom edge.
          const double x0 = k == 4 ? f.cols() - 3 + u(rng) : 30 + 40 * u(rng);
          const double y0 = k == 5 ? f.rows() - 3 + u(rng) : 30 + 30 * u(rng);
          const Vec3 v[3] = {on_ray(f, cam, x0, y0, 4 + u(rng)),
                             on_ray(f, cam, x0 + wide - 0.2 + 0.4 * u(rng), y0 + high * u(rng), 4 + u(rng)),
                             on_ray(f, cam, x0 + wide * u(rng), y0 + high - 0.2 + 0.4 * u(rng), 4 + u(rng))};
          bool taken = false;
          SampleRect box;
          const Hits h = by_tiny_path(f, v, taken, box);  // checks every kernel's entries
          if (!taken) continue;
          Hits in_box;  // the rasterizer's samples in the box (outside: rounding noise only)
          for (const auto& [x, y, t] : by_raster(f, v))
            if (x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1) in_box.emplace_back(x, y, t);
          EXPECT_EQ(h, in_box) << wide << "x" << high;
          const bool wide_box = box.x1 - box.x0 >= 4;  // more than one step a row
          one_step += !wide_box, more_steps += wide_box, cut += k >= 4;
        }
    EXPECT_GT(one_step, 300);
    EXPECT_GT(more_steps, 250);
    EXPECT_GT(cut, 200);
  }
}

TEST(TinyFaces, LargeOrBehindTheEyeIsNotTiny) {
  const Camera cam = camera(false);
  const SampleFrame f(cam, 1);
  const Vec3 big[3] = {on_ray(f, cam, 10, 10, 4), on_ray(f, cam, 30, 10, 4), on_ray(f, cam, 10, 30, 4)};
  bool taken = true;
  SampleRect box;
  by_tiny_path(f, big, taken, box);
  EXPECT_FALSE(taken);
  const Vec3 behind[3] = {cam.eye + Vec3{0, 0, 1}, on_ray(f, cam, 30, 10, 4), on_ray(f, cam, 10, 30, 4)};
  by_tiny_path(f, behind, taken, box);
  EXPECT_FALSE(taken);
  ProjectedVertex q[3];
  for (int i = 0; i < 3; ++i) q[i] = ProjectedVertex::of(f, on_ray(f, cam, 10.1 + 0.2 * i, 10.1, 4));
  EXPECT_EQ(sxmpvo::sample_box(f, q, 3, box), sxmpvo::BoxKind::None);  // no centre inside
}

// Triangles so far along their sample rays that their depth planes overflow: the edge
// tests accept samples (perspective: edge values that overflow, +inf or NaN, which reject
// nothing; orthographic: finite edges) whose t is not finite, so the AVX2 entries, placed
// by the edge tests first, must write such a step again. Every path gives the
// rasterizer's samples (none: no t is finite).
TEST(TinyFaces, AcceptedSamplesWithoutAFiniteDepthGiveNoEntry) {
  for (bool ortho : {false, true}) {
    Camera cam = camera(ortho);
    // Seen along an axis, a point far along a ray keeps its window position exactly.
    if (ortho) cam.eye = {0, 0, 9}, cam.target = {0, 0, 0}, cam.up = {0, 1, 0};
    const SampleFrame f(cam, 1);
    int taken_count = 0;
    for (double far : {1e155, 1e160, 1e200, 1e300}) {
      const Vec3 v[3] = {on_ray(f, cam, 49.7, 39.6, far), on_ray(f, cam, 52.4, 40.1, 1.1 * far),
                         on_ray(f, cam, 50.2, 42.6, 1.2 * far)};
      bool taken = false;
      SampleRect box;
      const Hits h = by_tiny_path(f, v, taken, box);  // checks the AVX2 and scalar entries against these
      taken_count += taken;
      if (taken) {
        EXPECT_EQ(h, by_raster(f, v)) << far;
      }
    }
    EXPECT_GT(taken_count, 0);
  }
}

// The AVX2 setup against the scalar one, bit for bit: random triangles, and triangles with
// edges along sample rows and columns seen along an axis, where an edge's ownership falls
// to the second and third of its tests (m . dx == 0 exactly).
TEST(TinyFaces, LaneSetupEqualsTheScalarSetup) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> grid(-3, 3);
  int ties = 0, cases = 0;
  for (bool ortho : {false, true}) {
    for (bool axis : {false, true}) {
      Camera c = camera(ortho);
      if (axis) c.eye = {0, 0, 9}, c.target = {0, 0, 0}, c.up = {0, 1, 0};
      const SampleFrame f(c, 1);
      for (int k = 0; k < 20000; ++k) {
        Vec3 v[3];
        for (Vec3& p : v) p = axis ? Vec3{0.25 * grid(rng), 0.25 * grid(rng), 0.5 * grid(rng)} : Vec3{u(rng), u(rng), u(rng)};
        const int s = k % 2 ? 1 : -1;
        RowEdges a, b;
        RowDepth da, db;
        const bool ra = sxmpvo::tiny_triangle_rows(f, v, s, a, da), rb = sxmpvo::tiny_triangle_rows_avx2(f, v, s, b, db);
        ASSERT_EQ(ra, rb) << k;
        if (!ra) continue;
        ++cases;
        for (int i = 0; i < 3; ++i) {
          ASSERT_EQ(std::memcmp(&a.mx[i], &b.mx[i], 8), 0) << k;
          ASSERT_EQ(std::memcmp(&a.my[i], &b.my[i], 8), 0) << k;
          ASSERT_EQ(std::memcmp(&a.mz[i], &b.mz[i], 8), 0) << k;
          ASSERT_EQ(std::memcmp(&a.c[i], &b.c[i], 8), 0) << k;
          ASSERT_EQ(a.own[i], b.own[i]) << k << " edge " << i;
          const Vec3 m{a.mx[i], a.my[i], a.mz[i]};
          ties += dot(m, f.affine_dx()) == 0;
        }
        ASSERT_EQ(std::memcmp(&da.n, &db.n, sizeof da.n), 0) << k;
        ASSERT_EQ(std::memcmp(&da.d, &db.d, 8), 0) << k;
        ASSERT_EQ(std::memcmp(&da.num, &db.num, 8), 0) << k;
        ASSERT_EQ(std::memcmp(&da.inv_nf, &db.inv_nf, 8), 0) << k;
      }
    }
  }
  EXPECT_GT(cases, 50000);
  EXPECT_GT(ties, 1000);  // the tie branches were reached
}
