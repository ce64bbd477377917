// renumber=true (MpvoCore::prepare, harness/scene/space_curve.h) in mpvo, mpvonc and sxmpvo:
// on meshes whose cells and points are shuffled, the orders are judged with zero
// violations, and orders and cycle reports are in the input's ids.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/space_curve.h"
#include "harness/view/view_set.h"
#include "tests/support/exact_views.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::testing;

namespace {
// An order of n ids that scatters neighbours: i -> (i * step + 3) mod n, step coprime to n.
std::vector<int32_t> scattered(size_t n, size_t step) {
  std::vector<int32_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<int32_t>((i * step + 3) % n);
  return v;
}
}  // namespace

TEST(Renumber, DeclaredOnceWithDefaultTrue) {
  for (const char* name : {"mpvo", "mpvonc", "sxmpvo"}) {
    const OrdererInfo& info = find_orderer(name);
    ASSERT_EQ(info.params.size(), 3u) << name;
    EXPECT_EQ(info.params[0].name, "renumber");
    EXPECT_EQ(info.params[0].def, true);
    EXPECT_EQ(info.params[1].name, "curve");
    EXPECT_EQ(info.params[1].def, "hilbert");
    EXPECT_EQ(info.params[2].name, "keep_coherent");
    EXPECT_EQ(info.params[2].def, true);
    EXPECT_THROW(make_orderer(std::string(name) + ":renumber=maybe"), InputError);
    EXPECT_THROW(make_orderer(std::string(name) + ":curve=peano"), InputError);
  }
}

TEST(Renumber, PrepareTimesItAsItsOwnPhase) {
  const Scene s = dataset("helix", {{"cells", "2000"}, {"shuffle", "3"}});
  for (const char* name : {"mpvo", "mpvonc", "sxmpvo"})
    for (bool on : {true, false}) {
      auto o = make_orderer(std::string(name) + (on ? "" : ":renumber=false"));
      PhaseClock clock;
      o->prepare(s.fresh(), clock);
      bool seen = false;
      for (const auto& [phase, _] : clock.phases()) seen |= phase == "renumber along a space curve";
      EXPECT_EQ(seen, on) << name;
    }
}

// Shuffled helix: SXMPVO exact at every pixel centre of 14 views, renumbered or not.
TEST(Renumber, SxmpvoExactOnAShuffledHelix) {
  const Scene s = dataset("helix", {{"cells", "2000"}, {"shuffle", "7"}});
  for (const char* spec : {"sxmpvo", "sxmpvo:keep_coherent=false", "sxmpvo:curve=morton,keep_coherent=false",
                           "sxmpvo:renumber=false"})
    expect_exact_views(spec, s, {200, 200, false, 1, ""}, [](const Ordering&, int) {});
}

// Shuffled convex block: MPVO and MPVONC respect every face arrow (decided in input ids by
// the exact predicate) and the oracle finds nothing, so the order is in input ids.
TEST(Renumber, MpvoAndMpvoncExactOnAShuffledConvexBlock) {
  const CellMesh block = tet_block(4, 3, 5);
  const Scene s = Scene::from_mesh(
      "shuffled block",
      permute_mesh(block, scattered(block.num_cells(), 7), scattered(block.num_points(), 11)));
  ViewOptions opt;
  opt.width = opt.height = 64;
  for (const Camera& view : fibonacci_views(s.bounds(), 14, opt))
    for (const char* spec : {"mpvo", "mpvonc", "mpvo:keep_coherent=false", "mpvonc:keep_coherent=false",
                             "mpvo:curve=morton,keep_coherent=false"}) {
      const Ordering o = run_orderer(spec, s, view);
      ASSERT_TRUE(is_permutation_of(o.order, s.num_primitives()));
      EXPECT_EQ(face_arrow_violations(s, view, o.order), 0) << spec;
      EXPECT_EQ(check_ordering(s, view, o.order).violating_fragments, 0) << spec;
      EXPECT_EQ(o.cycles.cycles, 0) << spec;
    }
}

// A visibility cycle among cells numbered far apart: reported with the input's ids.
TEST(Renumber, CycleReportsNameInputCells) {
  const CellMesh ring = blade_ring(8);
  const CellMesh both = append(translated(tet_block(2, 2, 2), {50, 50, 50}), ring);
  const std::vector<int32_t> order = scattered(both.num_cells(), 9);
  const Scene s = Scene::from_mesh("ring and block", permute_mesh(both, order, scattered(both.num_points(), 5)));
  std::set<int32_t> ring_ids;
  for (size_t c = 0; c < order.size(); ++c)
    if (order[c] >= static_cast<int32_t>(both.num_cells() - ring.num_cells())) ring_ids.insert(static_cast<int32_t>(c));
  for (const char* spec : {"mpvo", "mpvonc", "sxmpvo", "mpvo:keep_coherent=false", "mpvonc:keep_coherent=false",
                           "sxmpvo:keep_coherent=false", "mpvo:curve=morton,keep_coherent=false"}) {
    const Ordering o = run_orderer(spec, s, ring_axis_view(false));
    EXPECT_TRUE(is_permutation_of(o.order, s.num_primitives())) << spec;
    ASSERT_GE(o.cycles.cycles, 1) << spec;
    for (int32_t c : o.cycles.primitives) EXPECT_TRUE(ring_ids.count(c)) << spec << " reports cell " << c;
  }
  const Ordering p = run_orderer("mpvo", s, ring_axis_view(false));
  EXPECT_EQ(std::set<int32_t>(p.cycles.primitives.begin(), p.cycles.primitives.end()), ring_ids);
}

// keep_coherent: the block as generated (slab by slab, 5,400 cells a slab) keeps its
// numbering, so its orders are renumber=false's; shuffled (a point's ~20 users about 11,000
// cells apart, beyond kNearCells), the curve is chosen; the record says which (`renumbered`).
TEST(Renumber, KeepsTheInputNumberingWhenItIsMoreCoherent) {
  const CellMesh block = tet_block(30, 30, 40);  // 216,000 tets
  std::vector<int32_t> pts(block.num_points());
  for (size_t i = 0; i < pts.size(); ++i) pts[i] = static_cast<int32_t>(i);
  const Scene as_made = Scene::from_mesh("block", block);
  std::vector<int32_t> cells(block.num_cells());
  std::iota(cells.begin(), cells.end(), 0);
  std::shuffle(cells.begin(), cells.end(), std::mt19937(5));  // a mesher's disorder
  const Scene shuffled = Scene::from_mesh("shuffled", permute_mesh(block, cells, pts));
  ViewOptions opt;
  opt.width = opt.height = 64;
  const Camera view = fibonacci_views(as_made.bounds(), 14, opt)[3];
  for (const char* name : {"mpvonc", "sxmpvo"}) {
    const std::string n = name;
    const Ordering kept = run_orderer(n, as_made, view), off = run_orderer(n + ":renumber=false", as_made, view);
    EXPECT_EQ(kept.counters.at("renumbered"), 0.0) << name;
    EXPECT_EQ(kept.counters.at("far_reuse_input"), 0.0) << name;
    EXPECT_GT(kept.counters.at("far_reuse_curve"), 0.0) << name;
    EXPECT_EQ(kept.order, off.order) << name;
    EXPECT_EQ(run_orderer(n + ":keep_coherent=false", as_made, view).counters.at("renumbered"), 1.0) << name;
    const Ordering r = run_orderer(n, shuffled, view);
    EXPECT_EQ(r.counters.at("renumbered"), 1.0) << name;
    EXPECT_LT(r.counters.at("far_reuse_curve"), r.counters.at("far_reuse_input")) << name;
    EXPECT_EQ(check_ordering(shuffled, view, r.order).violating_fragments, 0) << name;
  }
}
