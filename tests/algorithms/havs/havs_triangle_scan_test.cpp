// HAVS's own triangle scan (triangle_scan.h) must give exactly PolygonRaster's fragments:
// every band of every view scanned both ways, the streams compared entry by entry (pixel,
// float depth, float scalar, tag), on perspective, orthographic and close-up views (an eye
// among the cells, where faces behind it take the generic path).
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <ostream>
#include <vector>

#include "algorithms/havs/face_bins.h"
#include "harness/cpu_features.h"
#include "tests/algorithms/havs/havs_views.h"
#include "tests/support/test_util.h"

namespace vob {
namespace {

struct Frag {
  int64_t pixel;
  havs::KEntry e;
  bool operator==(const Frag& o) const {
    return pixel == o.pixel && std::memcmp(&e, &o.e, sizeof e) == 0;  // bit for bit
  }
};

// Fragments of every band, fast and generic; returns the number compared.
int64_t compare_streams(const havs::FaceData& fd, const Camera& cam) {
  const SampleFrame frame(cam, 1);
  havs::FaceBins b;
  havs::bin_faces(fd, frame, test::havs_face_order(fd, cam), b);
  int64_t n = 0;
  for (int q = 0; q < b.bands; ++q) {
    std::vector<Frag> fast, generic;
    havs::scan_band(fd, frame, b, q, [&](int64_t p, const havs::KEntry& e) { fast.push_back({p, e}); });
    havs::scan_band(fd, frame, b, q, [&](int64_t p, const havs::KEntry& e) { generic.push_back({p, e}); }, true);
    EXPECT_EQ(fast.size(), generic.size()) << "band " << q;
    EXPECT_TRUE(fast == generic) << "band " << q;
    n += static_cast<int64_t>(generic.size());
  }
  return n;
}

class HavsTriangleScan : public ::testing::TestWithParam<std::string> {};

TEST_P(HavsTriangleScan, SameFragmentsAsPolygonRaster) {
  const Scene scene = test::small_mesh(GetParam());
  const havs::FaceData fd = havs::build_face_data(scene);
  int64_t total = 0;
  for (const bool ortho : {false, true})
    for (const double zoom : {1.0, 4.0})
      for (int v = 0; v < test::kHavsViews; v += 3) {
        ViewOptions o;
        o.width = 160, o.height = 120, o.ortho = ortho, o.zoom = zoom;
        total += compare_streams(fd, fibonacci_view(scene.bounds(), test::kHavsViews, v, o));
      }
  EXPECT_GT(total, 10000);  // not vacuous
}

INSTANTIATE_TEST_SUITE_P(Meshes, HavsTriangleScan, ::testing::Values("gap", "helix", "zoo"));

// An orthographic 16x16 view of z ~ 0 where pixel (i, j) is centred at world (i - 7.5, j - 7.5).
SampleFrame pixel_grid_frame() {
  Camera cam;
  cam.eye = {0, 0, 10};
  cam.ortho = true;
  cam.ortho_height = 16;
  cam.width = cam.height = 16;
  return SampleFrame(cam, 1);
}

// Samples exactly on edges (the meshes above never put one there): an orthographic 16x16
// view of z ~ 0 where pixel (i, j) is centred at world (i - 7.5, j - 7.5), a grid of quads
// with vertices on pixel centres cut along both diagonals, tilted so depths vary. Every
// sample on a shared edge must go to the same triangle as PolygonRaster decides it.
TEST(HavsTriangleScanExact, SamplesOnEdgesDecidedAsPolygonRaster) {
  const SampleFrame frame = pixel_grid_frame();
  const auto pt = [](int i, int j) { return Vec3{i - 7.5, j - 7.5, 0.01 * i - 0.02 * j}; };
  int64_t fragments = 0;
  for (int step : {1, 2, 3})
    for (int j = 0; j + step < 16; j += step)
      for (int i = 0; i + step < 16; i += step) {
        const Vec3 a = pt(i, j), b = pt(i + step, j), c = pt(i + step, j + step), d = pt(i, j + step);
        for (const std::array<Vec3, 3>& tri : {std::array<Vec3, 3>{a, b, c}, {a, c, d}, {a, b, d}, {b, c, d}}) {
          std::vector<std::array<double, 3>> fast, generic;
          havs::TriangleScan ts;
          if (ts.setup(frame, tri.data()))
            ts.scan(frame.bounds(), nullptr, [&](int sx, int sy, double t, const Vec3&) { fast.push_back({double(sx), double(sy), t}); });
          rasterize_polygon(frame, tri.data(), 3, frame.bounds(),
                            [&](int sx, int sy, double t) { generic.push_back({double(sx), double(sy), t}); });
          EXPECT_EQ(fast, generic) << "step " << step << " quad " << i << "," << j;
          fragments += static_cast<int64_t>(generic.size());
        }
      }
  EXPECT_GT(fragments, 1000);
}

// Where a front triangle comes from, for failure messages.
struct Where {
  const char* mesh;
  int view;
  bool ortho;
};
std::ostream& operator<<(std::ostream& os, const Where& w) {
  return os << w.mesh << " view " << w.view << (w.ortho ? " ortho" : "");
}

// visit(frame, tri, item, where) for every front triangle of every band item of the helix
// and zoo meshes over several views, perspective and orthographic; stops at a fatal failure.
template <class Visit>
void for_each_front_triangle(Visit&& visit) {
  for (const char* mesh : {"helix", "zoo"}) {
    const Scene scene = test::small_mesh(mesh);
    const havs::FaceData fd = havs::build_face_data(scene);
    const std::vector<Vec3>& points = scene.mesh().points;
    for (const bool ortho : {false, true})
      for (int v = 0; v < test::kHavsViews; v += 4) {
        ViewOptions o;
        o.width = 160, o.height = 120, o.ortho = ortho;
        const SampleFrame frame(fibonacci_view(scene.bounds(), test::kHavsViews, v, o), 1);
        havs::FaceBins b;
        havs::bin_faces(fd, frame, test::havs_face_order(fd, frame.camera()), b);
        for (const havs::BandItem& item : b.items) {
          if (item.ids[3] != havs::kFrontTriangle) continue;
          const Vec3 tri[3] = {points[item.ids[0]], points[item.ids[1]], points[item.ids[2]]};
          visit(frame, tri, item, Where{mesh, v, ortho});
          if (::testing::Test::HasFatalFailure()) return;
        }
      }
  }
}

// The row ranges' AVX2 kernel (four rows a step) against the scalar loop, bit for bit, on
// every front triangle of every band item of several views (the fragments above only show
// that a difference does not change coverage on these meshes; the ranges are the kernel's
// whole output). Skipped where the CPU has no AVX2.
TEST(HavsTriangleScanRanges, Avx2KernelMatchesTheScalarLoop) {
  if (!vob::cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar loop runs";
  constexpr int R = havs::TriangleScan::kRows;
  int64_t rows = 0, certain = 0;
  for_each_front_triangle([&](const SampleFrame& frame, const Vec3* tri, const havs::BandItem& item,
                              const Where& where) {
    havs::TriangleScan ts;
    if (!ts.setup(frame, tri)) return;
    // Row blocks of every height from the rectangle's bottom (the kernel's last step is
    // partial unless ny is a multiple of 4).
    for (int ny = 1; ny <= R; ny += 5) {
      int s[4][R], a[4][R];
      ts.row_ranges(item.rect.y0, ny, item.rect, s[0], s[1], s[2], s[3], true);
      ts.row_ranges(item.rect.y0, ny, item.rect, a[0], a[1], a[2], a[3]);
      for (int r = 0; r < ny; ++r) {
        for (int j = 0; j < 4; ++j) ASSERT_EQ(s[j][r], a[j][r]) << where << " row " << r << " bound " << j;
        certain += s[2][r] <= s[3][r];
      }
      rows += ny;
    }
  });
  EXPECT_GT(rows, 100000);  // not vacuous
  EXPECT_GT(certain, 1000);
}

// setup's AVX2 loop against its scalar loop, bit for bit: every field of every edge that is
// not flat, the flags and the choice of row_ranges' loop, on every front triangle of every
// band item of several views, perspective and orthographic, and on edges made flat or
// degenerate on purpose. Skipped where the CPU has no AVX2.
TEST(HavsTriangleScanSetup, Avx2LoopMatchesTheScalarLoop) {
  if (!vob::cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar loop runs";
  int64_t edges = 0, negative = 0;
  const auto compare = [&](const SampleFrame& frame, const Vec3* tri, const auto& where) {
    havs::TriangleScan fast, portable;
    const bool ok = fast.setup(frame, tri);
    ASSERT_EQ(ok, portable.setup(frame, tri, true)) << where;
    if (!ok) return;
    const havs::TriangleScan::Rows &f = fast.rows(), &p = portable.rows();
    ASSERT_EQ(fast.special(), portable.special()) << where;
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(f.flat[i], p.flat[i]) << where << " edge " << i;
      if (p.flat[i]) continue;
      ASSERT_EQ(f.finite[i], p.finite[i]) << where << " edge " << i;
      const double* fv[] = {f.lo0, f.hi0, f.slope, f.slack, f.sign, f.off_pos, f.off_neg};
      const double* pv[] = {p.lo0, p.hi0, p.slope, p.slack, p.sign, p.off_pos, p.off_neg};
      for (int j = 0; j < 7; ++j)
        ASSERT_EQ(std::memcmp(&fv[j][i], &pv[j][i], sizeof(double)), 0)
            << where << " edge " << i << " field " << j << ": " << fv[j][i] << " against " << pv[j][i];
      ++edges;
      negative += p.sign[i] < 0;
    }
  };
  for_each_front_triangle([&](const SampleFrame& frame, const Vec3* tri, const havs::BandItem&, const Where& where) {
    compare(frame, tri, where);
  });
  // Edges parallel to the sample rows (a = 0: flat) and to the columns, in an orthographic
  // 16x16 view where pixel (i, j) is centred at world (i - 7.5, j - 7.5).
  const SampleFrame frame = pixel_grid_frame();
  int flat = 0, infinite = 0;
  for (const std::array<Vec3, 3>& tri : {std::array<Vec3, 3>{Vec3{-3, -3, 0}, {4, -3, 0.5}, {0, 5, 1}},
                                          {Vec3{-3, -3, 0}, {-3, 4, 0.5}, {5, 0, 1}},
                                          {Vec3{-3.2, 1, 0}, {4.1, 1, 0}, {4.1, 6, 0.2}},
                                          {Vec3{1e-300, 0, 0}, {2e-300, 0, 0}, {0, 3, 0}},
                                          // a edge barely off the rows: b / a overflows (not finite)
                                          {Vec3{-3, 0, 0}, {4, 1e-309, 0.5}, {0, 5, 1}}}) {
    compare(frame, tri.data(), std::string("constructed"));
    havs::TriangleScan s;
    if (s.setup(frame, tri.data(), true))
      for (int i = 0; i < 3; ++i) flat += s.rows().flat[i], infinite += !s.rows().flat[i] && !s.rows().finite[i];
  }
  EXPECT_GT(edges, 10000);  // not vacuous
  EXPECT_GT(negative, 1000);  // both kinds of edge
  EXPECT_GT(flat, 0);
  EXPECT_GT(infinite, 0);
}

}  // namespace
}  // namespace vob
