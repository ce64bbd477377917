// The bsp-xmpvo plugin: object-space exact (no violation at the pixel centres nor between
// them, S = 3) on nonconvex, disconnected and zoo meshes over 14 views, perspective and
// orthographic, where MPVONC fails; relations across gaps; cycles reported and broken;
// skipped triangles counted when the eye is inside the mesh.
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

// bsp-xmpvo unless told otherwise.
struct Prepared : ReusedOrderer {
  explicit Prepared(const Scene& s, const std::string& spec = "bsp-xmpvo") : ReusedOrderer(s, spec) {}
};

// Every view of a 14-view set: complete, no cycle, zero violations at S (and at the pixel
// centres); returns the number of views where `control` violates.
int expect_exact(const Scene& s, int w, int h, bool ortho, int supersample, const std::string& control,
                 const std::string& spec = "bsp-xmpvo") {
  return expect_exact_views(spec, s, {w, h, ortho, supersample, control}, [](const Ordering& r, int) {
    for (const char* key : {"bsp_nodes", "bsp_depth", "bsp_fragments", "fragment_growth", "beam_queries",
                            "nodes_visited", "candidates", "overlap_tests", "relations", "bytes_bsp"})
      EXPECT_TRUE(r.counters.count(key)) << key;
    EXPECT_EQ(r.counters.at("skipped_triangles"), 0);
    EXPECT_EQ(r.counters.at("depth_undecided"), 0);
    EXPECT_LE(r.counters.at("relations"), r.counters.at("overlap_tests"));
  });
}

}  // namespace

TEST(BspXmpvo, ClaimsObjectExactAndCycles) {
  auto o = make_orderer("bsp-xmpvo");
  EXPECT_TRUE(o->claims().object_exact);
  EXPECT_TRUE(o->claims().detects_cycles);
  EXPECT_THROW(make_orderer("bsp-xmpvo:candidates=0"), InputError);
}

// Cook et al.'s Fig. 8 configuration, small: MPVONC fails in every view, BSP-XMPVO in none.
TEST(BspXmpvo, ExactOnHelixWhereMpvoncFails) {
  const Scene s = dataset("helix", {{"cells", "2000"}});
  EXPECT_EQ(expect_exact(s, 200, 200, false, 1, "mpvonc"), 14);
}

TEST(BspXmpvo, ExactOnGapMeshesBetweenPixelCentres) {
  for (const char* gaps : {"0", "3", "7"}) {
    const Scene s = dataset("gap", {{"nx", "5"}, {"ny", "5"}, {"nz", "12"}, {"gaps", gaps}});
    expect_exact(s, 120, 100, false, 3, "");
  }
}

TEST(BspXmpvo, ExactOnZooAndOrthographic) {
  expect_exact(dataset("zoo", {{"scale", "1"}}), 160, 160, false, 1, "");
  expect_exact(dataset("gap", {{"nx", "5"}, {"ny", "5"}, {"nz", "12"}, {"gaps", "5"}}), 120, 100, true, 1, "");
}

// Without the coverage stop every candidate in the beam is collected: still exact, and a
// superset of the relations found with the stop (same traversal order, truncated).
TEST(BspXmpvo, CollectAllIsExactAndASupersetOfStop) {
  const Scene s = dataset("helix", {{"cells", "1000"}});
  expect_exact(s, 100, 100, false, 3, "", "bsp-xmpvo:stop=false");
  Prepared stop(s), all(s, "bsp-xmpvo:stop=false");
  double stops = 0;
  for (int v = 0; v < 14; ++v) {
    const Camera view = fibonacci_view(s.bounds(), 14, v, ViewOptions{100, 100});
    const Ordering a = stop.order(view), b = all.order(view);
    EXPECT_LE(a.counters.at("relations"), b.counters.at("relations"));
    EXPECT_LE(a.counters.at("candidates"), b.counters.at("candidates"));
    EXPECT_EQ(b.counters.at("early_stops"), 0);
    stops += a.counters.at("early_stops");
  }
  EXPECT_GT(stops, 0);
}

// Two blocks side by side: the beams of one block's back faces meet the other's front
// faces, so there are relations, and each is between cells of different blocks.
TEST(BspXmpvo, RelationsAcrossTheGap) {
  const Scene s = Scene::from_mesh("two-blocks", two_blocks(3, 0.5));
  Prepared p(s);
  const Camera view = fibonacci_view(s.bounds(), 14, 2, ViewOptions{200, 200});
  const Ordering r = p.order(view);
  EXPECT_GT(r.counters.at("relations"), 0);
  EXPECT_GT(r.counters.at("beam_queries"), 0);
  EXPECT_TRUE(check_ordering(s, view, r.order).ok());
  EXPECT_EQ(ray_check(s, view, r.order).violations.size(), 0u);
}

// A convex mesh needs no relation at all.
TEST(BspXmpvo, ConvexMeshHasNoRelations) {
  const Scene s = Scene::from_mesh("block", tet_block(3, 3, 3));
  Prepared p(s);
  for (int v = 0; v < 14; ++v) {
    const Camera view = fibonacci_view(s.bounds(), 14, v, ViewOptions{100, 100});
    const Ordering r = p.order(view);
    EXPECT_EQ(r.counters.at("relations"), 0);
    EXPECT_TRUE(check_ordering(s, view, r.order).ok());
  }
}

// Visibility cycles: reported and broken, the order still complete.
TEST(BspXmpvo, ReportsCycles) {
  {
    const Scene s = Scene::from_mesh("blade-ring", blade_ring(8));
    Prepared p(s);
    const Ordering r = p.order(ring_axis_view(false));
    EXPECT_GT(r.cycles.cycles, 0);
    EXPECT_TRUE(is_permutation_of(r.order, s.mesh().num_cells()));
  }
  for (const char* name : {"cycle", "cycle-sticks"}) {
    const Scene s = dataset(name, {});
    Prepared p(s);
    int64_t cycles = 0;
    for (const Camera& v : find_dataset(name).views(s, 128, 128)) {
      const Ordering r = p.order(v);
      cycles += r.cycles.cycles;
      EXPECT_TRUE(is_permutation_of(r.order, s.mesh().num_cells()));
    }
    EXPECT_GT(cycles, 0) << name;
  }
}

// Eyes inside the mesh: triangles crossing the eye's plane are skipped and counted; the
// order is complete.
TEST(BspXmpvo, EyeInsideCountsSkippedTriangles) {
  const Scene s = dataset("eye-inside", {});
  Prepared p(s);
  double skipped = 0;
  for (const Camera& v : find_dataset("eye-inside").views(s, 128, 128)) {
    const Ordering r = p.order(v);
    skipped += r.counters.at("skipped_triangles");
    EXPECT_TRUE(is_permutation_of(r.order, s.mesh().num_cells()));
  }
  EXPECT_GT(skipped, 0);
}

// A far eye (1e8 from a gap mesh, a narrow field of view on one corner of it). The beam's
// edge planes through the eye were computed as (a - eye) x (b - eye), two nearly parallel
// vectors 1e8 long: the normal lost half its digits, the box cull then separated boxes the
// beam meets, and relations across the gaps went missing (2963 violating pixels here, 3394
// on gap 6x6x10, gaps=3; XMPVO none). From (a - eye) x (b - a) the normal is exact to
// rounding: no violation.
TEST(BspXmpvo, ExactFromAFarEye) {
  const Scene s = dataset("gap", {{"nx", "4"}, {"ny", "4"}, {"nz", "8"}, {"gaps", "3"}});
  Prepared p(s);
  const Vec3 target{0.5, 0.5, 0.6};
  for (double d : {1e6, 1e8}) {
    for (const Vec3 dir : {Vec3{0.6, 0.48, 0.64}, Vec3{-0.36, 0.8, 0.48}}) {
      Camera view;
      view.eye = target + dir * d;
      view.target = target;
      view.up = {0, 0, 1};
      view.width = view.height = 256;
      view.fov_deg = 2 * std::atan(1.5 / d) * 180 / 3.14159265358979323846;
      const Ordering r = p.order(view);
      const OracleResult o = check_ordering(s, view, r.order);
      EXPECT_GT(o.covered_pixels, 256 * 256 / 2) << "d " << d;
      EXPECT_EQ(o.violating_fragments, 0) << "d " << d << " " << o.examples.dump();
    }
  }
}
