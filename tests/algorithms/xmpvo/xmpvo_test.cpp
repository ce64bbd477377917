// The xmpvo plugin: zero oracle violations on nonconvex, disconnected and zoo meshes over
// 14 views (perspective and orthographic, at two sample densities), where MPVO alone fails;
// the exterior relations are what makes the difference; cycles reported and broken.
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/exact_views.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::testing;

namespace {

// 14 views: xmpvo exact, a permutation, no cycle. Returns how many views `control` fails.
int expect_exact_over_views(const Scene& s, int w, int h, bool ortho, int supersample,
                            const std::string& control) {
  return expect_exact_views("xmpvo", s, {w, h, ortho, supersample, control}, [](const Ordering& r, int) {
    const auto& k = r.counters;
    EXPECT_EQ(k.at("front_facing") + k.at("back_facing") + k.at("edge_on_faces"),
              k.at("exterior_faces"));
    EXPECT_EQ(k.at("skipped_faces"), 0);
    EXPECT_EQ(k.at("depth_undecided"), 0);
  });
}

}  // namespace

TEST(Xmpvo, ClaimsObjectExactAndCycles) {
  auto o = make_orderer("xmpvo");
  EXPECT_TRUE(o->claims().object_exact);
  EXPECT_TRUE(o->claims().detects_cycles);
  EXPECT_THROW(make_orderer("xmpvo:predicates=float"), InputError);
}

// Gaps between slabs: MPVO alone fails in some views, XMPVO in none.
TEST(Xmpvo, ExactOnGapMeshesWhereMpvoFails) {
  int mpvo_failures = 0;
  for (const char* gaps : {"0", "3", "7"}) {
    const Scene s = dataset("gap", {{"nx", "5"}, {"ny", "5"}, {"nz", "14"}, {"gaps", gaps}});
    mpvo_failures += expect_exact_over_views(s, 160, 120, false, 1, "mpvo");
  }
  EXPECT_GT(mpvo_failures, 0);
}

TEST(Xmpvo, ExactOnHelixPerspectiveOrthoAndSupersampled) {
  const Scene s = dataset("helix", {{"cells", "2000"}});
  EXPECT_EQ(expect_exact_over_views(s, 200, 200, false, 1, "mpvonc"), 14);
  expect_exact_over_views(s, 200, 200, true, 1, "");
  expect_exact_over_views(s, 120, 120, false, 4, "");
}

TEST(Xmpvo, ExactOnZooMesh) {
  const Scene s = dataset("zoo", {{"scale", "1"}});
  expect_exact_over_views(s, 200, 200, false, 1, "");
  expect_exact_over_views(s, 200, 200, true, 1, "");
}

// A hex block turned about an oblique axis, as gmsh or VTK leave a rotated structured mesh:
// its quads are planar only to rounding. XMPVO took them as planar and closed a cycle at
// the silhouette (gmsh's rotated 3x3x3 box: 2 of 14 views with violations); it now splits
// the warped ones into triangles (warped_quads.h).
TEST(Xmpvo, ExactOnARotatedHexBlockWithQuadsPlanarOnlyToRounding) {
  CellMesh m = hex_block(3);
  const Vec3 axis = normalize(Vec3{0.3, 0.5, 0.8});
  const double a = 0.651, c = std::cos(a), s = std::sin(a);
  for (Vec3& p : m.points)  // Rodrigues' rotation
    p = p * c + cross(axis, p) * s + axis * (dot(axis, p) * (1 - c));
  validate_cell_mesh(m, "rotated hex block");
  const Scene scene = Scene::from_mesh("rotated hex block", std::move(m));
  int split = 0;
  expect_exact_views("xmpvo", scene, {256, 256, false, 1, ""}, [&](const Ordering& r, int) {
    EXPECT_EQ(r.counters.at("depth_undecided"), 0);
    split += r.counters.at("warped_quads_split") > 0;
  });
  EXPECT_GT(split, 0) << "the rotation left every quad exactly planar: the test tests nothing";
}

// Two blocks with a gap: the relations across it are needed (MPVO's arrows alone leave
// the two blocks unordered), found, and the per-ray check agrees with the oracle.
TEST(Xmpvo, RelationsAcrossTheGap) {
  const Scene s = Scene::from_mesh("two-blocks", two_blocks(3, 0.5));
  int mpvo_failures = 0;
  for (int v = 0; v < 14; ++v) {
    const Camera view = fibonacci_view(s.bounds(), 14, v, ViewOptions{200, 200});
    const Outcome r = run_checked("xmpvo", s, view);
    EXPECT_TRUE(r.oracle.ok()) << "view " << v;
    EXPECT_EQ(ray_check(s, view, r.ordering.order).violations.size(), 0u) << "view " << v;
    const auto& k = r.ordering.counters;
    if (!run_checked("mpvo", s, view).oracle.ok()) {
      ++mpvo_failures;
      EXPECT_GT(k.at("relations"), 0) << "view " << v;
    }
    EXPECT_GT(k.at("projected_vertices"), 0);
    EXPECT_GT(k.at("ray_queries"), 0);
  }
  EXPECT_GT(mpvo_failures, 0);
}

// Compare mode counts decisions and disagreements and orders exactly like exact mode.
TEST(Xmpvo, CompareModeMatchesExact) {
  const Scene s = dataset("helix", {{"cells", "2000"}});
  const Camera view = fibonacci_view(s.bounds(), 14, 3, ViewOptions{200, 200});
  const Outcome exact = run_checked("xmpvo", s, view), compare = run_checked("xmpvo:predicates=compare", s, view);
  EXPECT_EQ(exact.ordering.order, compare.ordering.order);
  const auto& k = compare.ordering.counters;
  EXPECT_EQ(k.at("facing_decisions"), k.at("exterior_faces"));
  EXPECT_EQ(k.at("crossing_decisions"), k.at("candidate_edge_pairs"));
  EXPECT_GT(k.at("side_decisions"), 0);
  EXPECT_LE(k.at("disagree_side"), k.at("side_decisions"));  // disagreements are among the decisions
  EXPECT_EQ(exact.ordering.counters.count("disagree_side"), 0u);
}

// A visibility cycle across shared faces: reported and broken, the order still complete.
TEST(Xmpvo, ReportsCycles) {
  const Scene s = Scene::from_mesh("blade-ring", blade_ring(8));
  for (bool ortho : {false, true}) {
    const Outcome r = run_checked("xmpvo", s, ring_axis_view(ortho));
    EXPECT_GT(r.ordering.cycles.cycles, 0);
    EXPECT_TRUE(is_permutation_of(r.ordering.order, s.mesh().num_cells()));
  }
}
