// The AVX2 row kernel against the scalar loop: the same samples with bit-identical t, for
// random triangles in perspective and orthographic views, with vertices on sample rays (so
// that edge values are exactly zero and the top-left rule decides), spans of every length
// up to a chunk and starting at every column offset, edge-on and behind-the-eye triangles.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "harness/cpu_features.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/row_coverage.h"
#include "tests/support/test_meshes.h"

using namespace vob;

namespace {

RowEdges edges_of(const PolygonRaster::Edge* e) {
  RowEdges r;
  for (int i = 0; i < 3; ++i)
    r.mx[i] = e[i].m.x, r.my[i] = e[i].m.y, r.mz[i] = e[i].m.z, r.c[i] = e[i].c, r.own[i] = e[i].own;
  return r;
}

struct Tally {
  int64_t rows = 0, hits = 0, zero_rows = 0;
};

// Compares the two kernels on every row and many spans of triangle v.
void compare(const SampleFrame& f, const Vec3* v, Tally& tally) {
  PolygonRaster::Edge e[3];
  PolygonRaster::DepthPlane p;
  if (!PolygonRaster::triangle_edges(f, v[0], v[1], v[2], e)) return;
  if (!PolygonRaster::depth_plane(f, v, 3, p)) return;
  const RowEdges re = edges_of(e);
  const RowDepth rd{p.plane.n, p.plane.d, p.num, p.inv_nf};
  const RowCoverageFn base = row_coverage_baseline();
  RowHits a, b;
  for (const RowCoverageFn fast : {row_coverage_avx2(), row_coverage_avx512()}) {
    if (!fast) continue;  // a kernel this CPU cannot run
  for (int sy = 0; sy < f.rows(); ++sy)
    for (int x0 = 0; x0 < f.cols(); x0 += 5)
      for (int len : {1, 2, 3, 4, 5, 7, 8, 13, kRowChunk}) {
        const int x1 = std::min(f.cols() - 1, x0 + len - 1);
        // The span, and below it spans of the next rows, one shorter: several spans of
        // several lengths in one call (one to three, so that the AVX-512 kernel's pairs of
        // runs also end with a run alone).
        const int x2 = std::max(x0, x1 - 1);
        const RowSpan spans[3] = {{sy, x0, x1}, {(sy + 1) % f.rows(), x0, x2}, {(sy + 2) % f.rows(), x2, x1}};
        const int count = 1 + (sy + x0 / 5) % 3;
        const int na = base(f, re, rd, spans, count, a), nb = fast(f, re, rd, spans, count, b);
        ++tally.rows;
        ASSERT_EQ(na, nb) << "row " << sy << " [" << x0 << ", " << x1 << "]";
        for (int j = 0; j < na; ++j) {
          ASSERT_EQ(a.sx[j], b.sx[j]);
          ASSERT_EQ(a.sy[j], b.sy[j]);
          ASSERT_EQ(std::memcmp(&a.t[j], &b.t[j], sizeof(double)), 0)
              << "t " << a.t[j] << " vs " << b.t[j] << " at (" << a.sx[j] << ", " << a.sy[j] << ")";
        }
        tally.hits += na;
        for (int sx = x0; sx <= x1; ++sx) {
          const Vec3 x = f.x(sx, sy);
          for (int i = 0; i < 3; ++i)
            if (re.c[i] + (re.mx[i] * x.x + re.my[i] * x.y + re.mz[i] * x.z) == 0) {
              ++tally.zero_rows;
              sx = x1, i = 3;
            }
        }
      }
  }
}

void run(bool ortho, Tally& tally) {
  const Camera cam = test::test_camera({1.3, -4.1, 3.7}, {0.1, 0.2, 0}, 24, 20, ortho, 3.0);
  const SampleFrame f(cam, 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    Vec3 v[3];
    for (int i = 0; i < 3; ++i) {
      // Every other triangle has its corners on sample rays (exact zeros on edges through
      // two of them); some reach behind the eye.
      double wx = 24 * u(rng), wy = 20 * u(rng);
      if (k % 2 == 0) wx = std::floor(wx) + 0.5, wy = std::floor(wy) + 0.5;
      const Ray r = cam.ray(wx, wy);
      const double s = (k % 7 == 0 && i == 0) ? -0.5 : 2 + 4 * u(rng);
      v[i] = r.origin + r.dir * s;
    }
    if (k % 11 == 0) v[2] = v[0] + (v[1] - v[0]) * 0.37;  // degenerate: a segment
    compare(f, v, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

}  // namespace

// Every lane kernel this CPU runs (AVX2, AVX-512) against the scalar loop.
TEST(RowCoverage, Avx2KernelMatchesTheScalarLoopBitForBit) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: only the scalar loop runs";
  for (bool ortho : {false, true}) {
    Tally tally;
    run(ortho, tally);
    if (HasFatalFailure()) return;
    // The comparison must have seen covered samples and exact-zero edge values.
    EXPECT_GT(tally.hits, 1000) << (ortho ? "ortho" : "perspective");
    EXPECT_GT(tally.zero_rows, 10) << (ortho ? "ortho" : "perspective");
    std::printf("%s: %lld spans, %lld hits, %lld spans with an exact zero\n", ortho ? "ortho" : "perspective",
                (long long)tally.rows, (long long)tally.hits, (long long)tally.zero_rows);
  }
}

// PolygonRaster::triangle_edges' AVX2 lanes against its scalar loop, every field bit for
// bit: random triangles; corners on a lattice so that coordinates tie (the lexicographic
// order decided by y or z), edges parallel to the rows or columns of an axis-aligned view
// (a == 0 or b == 0: the top-left rule's later tests), signed zeros, repeated corners.
TEST(RowCoverage, TriangleEdgesAvx2MatchTheScalarLoopBitForBit) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: only the scalar loop runs";
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::uniform_int_distribution<int> lattice(-2, 2);
  int64_t compared = 0, a_zero = 0, ab_zero = 0, owned = 0;
  for (const bool ortho : {false, true})
    for (const bool aligned : {false, true}) {
      const Camera cam = aligned ? test::test_camera({0, 0, 9}, {0, 0, 0}, 16, 16, ortho, 8.0)
                                 : test::test_camera({1.3, -4.1, 3.7}, {0.1, 0.2, 0}, 24, 20, ortho, 3.0);
      const SampleFrame f(cam, 1);
      for (int k = 0; k < 4000; ++k) {
        Vec3 v[3];
        for (Vec3& p : v)
          p = k % 2 ? Vec3{u(rng), u(rng), u(rng)} : Vec3{double(lattice(rng)), double(lattice(rng)), lattice(rng) * 0.5};
        if (k % 4 == 0) v[1].z = -0.0, v[2].z = 0.0;
        if (k % 13 == 0) v[2] = v[0];  // a repeated corner
        // An edge in the eye's plane, seen along the view (perspective): a == b == 0 with
        // m != 0, where the rule's last test decides.
        if (!ortho && k % 5 == 1) v[0].z = v[1].z = cam.eye.z;
        PolygonRaster::Edge s[3], a[3];
        const bool rs = PolygonRaster::triangle_edges(f, v[0], v[1], v[2], s, true);
        const bool ra = PolygonRaster::triangle_edges(f, v[0], v[1], v[2], a);
        ASSERT_EQ(rs, ra) << "triangle " << k;
        if (!rs) continue;
        for (int i = 0; i < 3; ++i) {
          const double fs[] = {s[i].m.x, s[i].m.y, s[i].m.z, s[i].c, s[i].a, s[i].b, s[i].k, s[i].eta};
          const double fa[] = {a[i].m.x, a[i].m.y, a[i].m.z, a[i].c, a[i].a, a[i].b, a[i].k, a[i].eta};
          ASSERT_EQ(std::memcmp(fs, fa, sizeof fs), 0) << "triangle " << k << " edge " << i;
          ASSERT_EQ(s[i].own, a[i].own) << "triangle " << k << " edge " << i;
          a_zero += s[i].a == 0;
          ab_zero += s[i].a == 0 && s[i].b == 0 && s[i].own;
          owned += s[i].own;
        }
        ++compared;
      }
    }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(a_zero, 100);  // the top-left rule's tie-breaks were exercised, the last too
  EXPECT_GT(ab_zero, 10);
  EXPECT_GT(owned, 1000);
}
