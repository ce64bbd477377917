// MpvoCore and the mpvo / mpvonc plugins: arrows decided exactly, DFS with extra
// relations, cycles broken and reported, deep searches, and the orders MPVO promises.
#include <gtest/gtest.h>

#include <algorithm>

#include <random>

#include "algorithms/mpvo/mpvo_core.h"
#include "harness/bench/registry.h"
#include "harness/geometry/predicates.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::testing;

namespace {

// The plain MPVO DFS after create_partial_order: from the sinks, then from what they left.
Ordering dfs_from_sinks(mpvo::MpvoCore& core) {
  Ordering o;
  core.begin_dfs(o);
  core.dfs_sinks(o);
  core.dfs_unvisited(o);
  return o;
}

// Two tets far apart: no shared face, so no arrows; cells 0 and 1 are both sinks.
CellMesh two_loose_tets() {
  CellMesh a;
  a.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  a.add_cell(CellType::Tetra, {0, 1, 2, 3});
  CellMesh b = a;
  for (Vec3& p : b.points) p += Vec3{5, 0, 0};
  return append(a, b);
}

}  // namespace

TEST(ExtraRelations, BuildsCsrAndNotSinkFlags) {
  mpvo::ExtraRelations x;
  x.build_from_pairs(4, {{2, 0}, {2, 3}, {0, 1}});
  ASSERT_EQ(x.offsets, (std::vector<int32_t>{0, 1, 1, 3, 3}));
  EXPECT_EQ(x.behind, (std::vector<int32_t>{1, 0, 3}));
  EXPECT_EQ(x.not_sink, (std::vector<uint8_t>{1, 1, 0, 1}));
  EXPECT_THROW(x.build_from_pairs(2, {{0, 2}}), std::out_of_range);
}

// Both ways of sort_unique_pairs (counting passes where the ids' range is small, std::sort
// where it is large) give std::sort + std::unique's pairs; an id out of range is an error.
TEST(SortUniquePairs, MatchesSortAndUnique) {
  std::mt19937 rng(7);
  for (const size_t cells : {size_t(1), size_t(50), size_t(3000), size_t(1) << 20}) {
    std::vector<std::pair<int32_t, int32_t>> pairs;
    for (int i = 0; i < 2000; ++i) {
      const int32_t a = int32_t(rng() % cells), b = int32_t(rng() % cells);
      pairs.emplace_back(a, b);
      if (i % 3 == 0) pairs.emplace_back(a, b);  // a repeat
    }
    auto expected = pairs;
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    mpvo::sort_unique_pairs(pairs, cells);
    EXPECT_EQ(pairs, expected) << cells << " cells";
  }
  std::vector<std::pair<int32_t, int32_t>> bad{{0, 1}, {2, 0}};
  EXPECT_THROW(mpvo::sort_unique_pairs(bad, 2), std::out_of_range);
  std::vector<std::pair<int32_t, int32_t>> none;
  mpvo::sort_unique_pairs(none, 0);
  EXPECT_TRUE(none.empty());
}

TEST(MpvoCore, ExtraRelationsAreEligibleNeighboursAndCyclesAreBroken) {
  Scene s = Scene::from_mesh("loose", two_loose_tets());
  mpvo::MpvoCore core;
  core.bind(s);
  const Camera view = fibonacci_view(s.bounds(), 1, 0);
  core.create_partial_order(view);
  EXPECT_EQ(core.arrows(), 0);
  {
    const Ordering o = dfs_from_sinks(core);
    EXPECT_EQ(o.order, (std::vector<int32_t>{0, 1}));
  }
  {
    mpvo::ExtraRelations x;
    x.build_from_pairs(2, {{0, 1}});  // 1 behind 0: 1 is drawn first, 0 is the only sink
    Ordering o;
    core.begin_dfs(o, &x);
    EXPECT_FALSE(core.is_sink(1));
    core.dfs_sinks(o);
    core.dfs_unvisited(o);
    core.add_counters(o);
    EXPECT_EQ(o.order, (std::vector<int32_t>{1, 0}));
    EXPECT_EQ(o.counters["sink_cells"], 1);
    EXPECT_EQ(o.cycles.cycles, 0);
  }
  {
    mpvo::ExtraRelations x;
    x.build_from_pairs(2, {{0, 1}, {1, 0}});  // a 2-cycle with no sink
    Ordering o;
    core.begin_dfs(o, &x);
    core.dfs_sinks(o);
    core.dfs_unvisited(o);
    core.add_counters(o);
    EXPECT_TRUE(is_permutation_of(o.order, 2));
    EXPECT_EQ(o.cycles.cycles, 1);
    EXPECT_EQ(o.cycles.primitives, (std::vector<int32_t>{0, 1}));
    EXPECT_EQ(o.counters["sink_cells"], 0);
    EXPECT_EQ(o.counters["cycle_roots"], 1);
  }
}

// The root loops skip eight cells a word at a time: on 21 loose tets (no arrows, so every
// cell is a sink unless a relation puts something in front of it) the sinks' searches run
// in id order, and the cycle left for dfs_unvisited lies past the first, fully output word.
TEST(MpvoCore, RootLoopsFindSinksAndCyclesPastTheFirstWord) {
  CellMesh mesh = two_loose_tets();
  for (int k = 1; k < 10; ++k) {
    CellMesh more = two_loose_tets();
    for (Vec3& p : more.points) p += Vec3{0, 3.0 * k, 0};
    mesh = append(mesh, more);
  }
  CellMesh last;  // one more tet: 21 cells, a partial last word
  last.points = {{0, 0, 7}, {1, 0, 7}, {0, 1, 7}, {0, 0, 8}};
  last.add_cell(CellType::Tetra, {0, 1, 2, 3});
  mesh = append(mesh, last);
  Scene s = Scene::from_mesh("loose", mesh);
  ASSERT_EQ(s.num_primitives(), 21u);
  mpvo::MpvoCore core;
  core.bind(s);
  core.create_partial_order(fibonacci_view(s.bounds(), 1, 0));
  ASSERT_EQ(core.arrows(), 0);
  mpvo::ExtraRelations x;
  x.build_from_pairs(21, {{9, 17}, {17, 9}, {20, 3}});  // a 2-cycle; 3 behind 20
  Ordering o;
  core.begin_dfs(o, &x);
  core.dfs_sinks(o);
  core.dfs_unvisited(o);
  core.add_counters(o);
  EXPECT_EQ(o.order, (std::vector<int32_t>{0, 1, 2, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 18, 19, 3, 20,
                                           17, 9}));
  EXPECT_EQ(o.counters["sink_cells"], 18);
  EXPECT_EQ(o.counters["cycle_roots"], 1);
  EXPECT_EQ(o.cycles.cycles, 1);
}

// The sparse form (SXMPVO's): the same traversal as the dense one; a second frame with
// other relations reads no stale span entry of the first.
TEST(MpvoCore, SparseExtraRelations) {
  Scene s = Scene::from_mesh("loose", two_loose_tets());
  mpvo::MpvoCore core;
  core.bind(s);
  core.create_partial_order(fibonacci_view(s.bounds(), 1, 0));
  mpvo::ExtraRelations x;
  x.span.assign(2, {0, 0});
  for (int32_t front : {0, 1}) {
    x.cells = {front};
    x.behind = {1 - front};
    x.span[front] = {0, 1};
    Ordering o;
    core.begin_dfs(o, &x);
    EXPECT_FALSE(core.is_sink(1 - front));
    EXPECT_TRUE(core.is_sink(front));
    core.dfs_sinks(o);
    core.dfs_unvisited(o);
    core.add_counters(o);
    EXPECT_EQ(o.order, (std::vector<int32_t>{1 - front, front}));
    EXPECT_EQ(o.counters["sink_cells"], 1);
  }
  x.span.resize(1);
  Ordering o;
  EXPECT_THROW(core.begin_dfs(o, &x), std::invalid_argument);
}

TEST(MpvoCore, EyeOnFacePlanesGetsExactZeroSigns) {
  // Integer grid: the eye lies exactly in the planes x = 1 and y = z of some faces.
  Scene s = Scene::from_mesh("block", tet_block(3, 3, 3));
  mpvo::MpvoCore core;
  core.bind(s);
  Camera view;
  view.eye = {1, -4, -4};
  view.target = {1.5, 1.5, 1.5};
  core.create_partial_order(view);
  EXPECT_GT(core.exact_sign_calls(), 0);
  const CellMesh& m = s.mesh();
  const MeshFaces& f = s.faces();
  int zeros = 0;
  for (size_t i = 0; i < f.num_faces(); ++i) {
    const int32_t* v = f.face_points(i);
    const int exact = orient3d(m.points[v[0]], m.points[v[1]], m.points[v[2]], view.eye);
    ASSERT_EQ(core.face_sign(static_cast<int32_t>(i)), exact) << "face " << i;
    zeros += exact == 0;
  }
  EXPECT_GT(zeros, 0);
  const Ordering o = dfs_from_sinks(core);
  EXPECT_TRUE(is_permutation_of(o.order, m.num_cells()));
  EXPECT_EQ(face_arrow_violations(s, view, o.order), 0);
}

TEST(MpvoCore, NearPlaneEyesAreDecidedExactlyAndWrongDoubleSignsCounted) {
  // Off-grid coordinates and eyes placed (in rounded arithmetic) on the shared face's
  // plane: the double sign is noise there, the exact one must win.
  CellMesh m;
  m.points = {{0.1, 0.2, 0.3}, {1.7, 0.33, 0.1}, {0.3, 1.9, 0.7}, {0.2, 0.4, 1.3}, {1.1, 1.3, -0.9}};
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  if (orient3d(m.points[0], m.points[1], m.points[2], m.points[3]) < 0) std::swap(m.conn[1], m.conn[2]);
  m.add_cell(CellType::Tetra, {0, 2, 1, 4});
  if (orient3d(m.points[0], m.points[2], m.points[1], m.points[4]) < 0) std::swap(m.conn[5], m.conn[6]);
  validate_cell_mesh(m, "pair");
  Scene s = Scene::from_mesh("pair", m);
  mpvo::MpvoCore core;
  core.bind(s);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  int64_t exact = 0, wrong = 0;
  const Vec3 a = m.points[0], b = m.points[1], c = m.points[2];
  for (int t = 0; t < 400; ++t) {
    Camera view;
    view.eye = a + (b - a) * u(rng) + (c - a) * u(rng);
    view.target = view.eye + Vec3{0.3, 0.2, 1.0};
    core.create_partial_order(view);
    exact += core.exact_sign_calls();
    wrong += core.double_sign_wrong();
    const MeshFaces& f = s.faces();
    for (size_t i = 0; i < f.num_faces(); ++i) {
      const int32_t* v = f.face_points(i);
      ASSERT_EQ(core.face_sign(static_cast<int32_t>(i)),
                orient3d(m.points[v[0]], m.points[v[1]], m.points[v[2]], view.eye));
    }
  }
  EXPECT_GE(exact, 400);  // the shared face at least, every time
  EXPECT_GT(wrong, 0);
}

TEST(MpvoCore, OrthographicSignsMatchTheExactPredicate) {
  Scene s = Scene::from_mesh("block", tet_block(3, 3, 3));
  mpvo::MpvoCore core;
  core.bind(s);
  Camera view;
  view.ortho = true;
  view.eye = {1.5, -6, 1.5};  // looking along +y: faces containing the y axis are edge-on
  view.target = {1.5, 1.5, 1.5};
  core.create_partial_order(view);
  const CellMesh& m = s.mesh();
  const MeshFaces& f = s.faces();
  int zeros = 0;
  for (size_t i = 0; i < f.num_faces(); ++i) {
    const int32_t* v = f.face_points(i);
    const int exact = -orient_direction(m.points[v[0]], m.points[v[1]], m.points[v[2]], view.forward());
    ASSERT_EQ(core.face_sign(static_cast<int32_t>(i)), exact);
    zeros += exact == 0;
  }
  EXPECT_GT(zeros, 0);
  EXPECT_GT(core.exact_sign_calls(), 0);
}

TEST(MpvoCore, DeepSearchDoesNotUseTheCallStack) {
  // A 1 x 1 x 40000 column seen from its end: the DFS goes 40000+ cells deep.
  Scene s = Scene::from_mesh("column", tet_block(1, 1, 40000));
  mpvo::MpvoCore core;
  core.bind(s);
  Camera view;
  view.eye = {0.5, 0.4, -3};
  view.target = {0.5, 0.5, 10};
  core.create_partial_order(view);
  const Ordering o = dfs_from_sinks(core);
  ASSERT_TRUE(is_permutation_of(o.order, s.num_primitives()));
  EXPECT_EQ(face_arrow_violations(s, view, o.order), 0);
  // Back to front: the far end of the column first.
  EXPECT_GT(s.mesh().cell_centroid(o.order.front()).z, 39999);
  EXPECT_LT(s.mesh().cell_centroid(o.order.back()).z, 1);
}

TEST(Mpvo, ConvexBlockRespectsEveryFaceOver14Views) {
  Scene s = Scene::from_mesh("block", tet_block(4, 4, 4));
  for (bool ortho : {false, true}) {
    ViewOptions opt;
    opt.ortho = ortho;
    for (const Camera& view : fibonacci_views(s.bounds(), 14, opt))
      for (const char* spec : {"mpvo", "mpvonc"}) {
        const Ordering o = run_orderer(spec, s, view);
        ASSERT_TRUE(is_permutation_of(o.order, s.num_primitives()));
        EXPECT_EQ(face_arrow_violations(s, view, o.order), 0) << spec;
        EXPECT_EQ(o.cycles.cycles, 0) << spec;
        EXPECT_GT(o.counters.at("arrows"), 0) << spec;
        EXPECT_GE(o.counters.at("sink_cells"), 1) << spec;
        EXPECT_EQ(o.counters.at("cycle_roots"), 0) << spec;
      }
  }
}

TEST(Mpvo, ConvexBlockIsExactAlongPixelRays) {
  Scene s = Scene::from_mesh("block", tet_block(3, 3, 3));
  ViewOptions opt;
  opt.width = opt.height = 48;
  for (const Camera& view : fibonacci_views(s.bounds(), 14, opt))
    for (const char* spec : {"mpvo", "mpvonc"}) {
      const RayCheck r = ray_check(s, view, run_orderer(spec, s, view).order);
      EXPECT_GT(r.pairs_checked, 0);
      EXPECT_TRUE(r.violations.empty()) << spec << ": " << r.violations.size() << " pairs";
    }
}

TEST(Mpvo, MissesTheRelationAcrossAGap) {
  // Block A (cells [0, 6n^3)) and block B side by side along x. MPVO takes the sinks in
  // id order and so draws all of A before B: wrong wherever A occludes B, which some of
  // the 14 views (eye on A's side) show.
  const int n = 2;
  Scene s = Scene::from_mesh("two-blocks", two_blocks(n, 0.5));
  const int32_t a_cells = 6 * n * n * n;
  ViewOptions opt;
  opt.width = opt.height = 48;
  int64_t cross_violations = 0, mpvonc_cross = 0;
  for (const Camera& view : fibonacci_views(s.bounds(), 14, opt)) {
    const Ordering o = run_orderer("mpvo", s, view);
    EXPECT_EQ(face_arrow_violations(s, view, o.order), 0);  // within blocks MPVO is right
    for (const auto& [early, late] : ray_check(s, view, o.order).violations)
      cross_violations += (early < a_cells) != (late < a_cells);
    for (const auto& [early, late] : ray_check(s, view, run_orderer("mpvonc", s, view).order).violations)
      mpvonc_cross += (early < a_cells) != (late < a_cells);
  }
  EXPECT_GT(cross_violations, 0);
  // MPVONC's centroid ordering of the exterior cells fixes this easy case.
  EXPECT_EQ(mpvonc_cross, 0);
}

TEST(Mpvonc, CountsExteriorCellsAndReportsTheRingCycle) {
  Scene ring = Scene::from_mesh("ring", blade_ring(8));
  const Ordering o = run_orderer("mpvonc", ring, ring_axis_view(false));
  EXPECT_TRUE(is_permutation_of(o.order, 8));
  EXPECT_EQ(o.counters.at("exterior_cells"), 8);
  EXPECT_GE(o.cycles.cycles, 1);
  const Ordering p = run_orderer("mpvo", ring, ring_axis_view(false));
  EXPECT_EQ(p.counters.at("sink_cells"), 0);  // every wedge has one in front of it
  EXPECT_EQ(p.counters.at("cycle_roots"), 1);
  EXPECT_EQ(p.cycles.primitives.size(), 8u);  // the whole ring
}
