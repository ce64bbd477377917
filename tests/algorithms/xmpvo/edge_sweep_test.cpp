// XMPVO's edge sweep (edge_sweep.cpp) finds the same relations as a full query at every
// arrangement vertex, where it runs (generated meshes) and where its premises fail and it
// falls back (touching volumes, hard cases); the orders stay valid; one and two threads agree.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "algorithms/xmpvo/edge_contacts.h"
#include "algorithms/xmpvo/query_worker.h"
#include "algorithms/xmpvo/ray_queries.h"
#include "datasets/datasets.h"
#include "datasets/generators/view_cases.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::xmpvo;
using namespace vob::test;

namespace {

struct Relations {
  std::vector<std::pair<int32_t, int32_t>> pairs;
  QueryStats stats;
};

Relations relations(const Scene& s, const Camera& view, bool sweep, bool quick_sides = true,
                    bool sweep_ends = true, int unswept_sheet = 1) {
  const ExteriorFaces& ext = s.exterior_faces();
  std::vector<FacePlane> plane;
  for (size_t i = 0; i < ext.face.size(); ++i) plane.push_back(FacePlane::of(&ext.corners[4 * i]));
  Signs signs;
  signs.g = ViewGeometry::of(view);
  Projection proj;
  const Aabb box = s.mesh().bounds();
  proj.run(ext, view, signs, box.center(), box.radius());
  const EdgeContacts contacts = find_edge_contacts(ext);
  const bool conforming = contacts.triangles_only && contacts.touched_edges == 0;  // as the orderer
  Arrangement arr;
  arr.set_faces(ext);
  arr.unswept_sheet = conforming ? unswept_sheet : 0;
  int64_t candidates = arr.build(ext, proj, signs);
  Relations r;
  QueryInput in{signs, ext, plane, proj, arr, sweep};
  in.conforming = conforming;
  in.quick_sides = quick_sides;
  in.sweep_ends = sweep_ends;
  r.pairs = view_relations(in, arr, signs, r.stats, candidates);
  return r;
}

// Every view of the scene: the same relations without the sweep, with it on every edge, and
// with it leaving out the front or the back sheet's inner edges and their crossings with
// each other (Arrangement::unswept_sheet, on conforming surfaces, as the orderer);
// returns the crossings the sweep answered by a swap (comparison-free on conforming
// surfaces). `unswept`: edges left out over the views, with either sheet.
int64_t same_relations(const Scene& s, int views, bool ortho = false, int64_t* unswept = nullptr) {
  int64_t swept = 0;
  for (int v = 0; v < views; ++v) {
    ViewOptions o{160, 160};
    o.ortho = ortho;
    const Camera view = fibonacci_view(s.bounds(), views, v, o);
    const Relations off = relations(s, view, false, true, true, 0);
    EXPECT_EQ(off.stats.sweep_crossings, 0);
    // Full queries from an arrangement that left crossings out: built again (view_relations).
    const Relations again = relations(s, view, false);
    EXPECT_EQ(again.pairs, off.pairs) << "view " << v;
    for (int sheet : {0, 1, -1}) {
      const Relations on = relations(s, view, true, true, true, sheet);
      EXPECT_EQ(on.pairs, off.pairs) << "view " << v << ", unswept sheet " << sheet;
      if (sheet == 0) {
        EXPECT_EQ(on.stats.sheet_edges_unswept, 0);
        swept += on.stats.sweep_swaps;
      }
      if (unswept) *unswept += on.stats.sheet_edges_unswept;
    }
  }
  return swept;
}

}  // namespace

TEST(XmpvoEdgeSweep, SameRelationsOnGeneratedMeshes) {
  int64_t unswept = 0;
  EXPECT_GT(same_relations(dataset("helix", {{"cells", "3000"}}), 6, false, &unswept), 0);
  EXPECT_GT(same_relations(dataset("helix", {{"cells", "3000"}}), 4, true, &unswept), 0);
  EXPECT_GT(same_relations(dataset("gap", {{"nx", "5"}, {"ny", "5"}, {"nz", "9"}, {"gaps", "2"}}), 6, false, &unswept), 0);
  EXPECT_GT(same_relations(dataset("zoo"), 6, false, &unswept), 0);
  EXPECT_GT(unswept, 0);
}

TEST(XmpvoEdgeSweep, SameRelationsOnHardCases) {
  for (const char* name : {"touching-conforming", "touching-shifted", "touching-rotated", "touching-overhang",
                           "touching-edge", "touching-hex", "offset", "slivers", "edge-on"}) {
    SCOPED_TRACE(name);
    same_relations(dataset(name), 3);
  }
}

// The orderer with the sweep: valid orders, and the sweep answered the crossings.
TEST(XmpvoEdgeSweep, OrdersStayValid) {
  const Scene s = dataset("helix", {{"cells", "3000"}});
  for (int v = 0; v < 4; ++v) {
    const Camera view = fibonacci_view(s.bounds(), 14, v, ViewOptions{200, 200});
    const Outcome o = run_checked("xmpvo", s, view);
    EXPECT_TRUE(o.oracle.ok()) << v;
    EXPECT_GT(o.ordering.counters.at("sweep_crossings"), 0);
    EXPECT_LE(o.ordering.counters.at("sweep_fallbacks"), o.ordering.counters.at("sweep_edges"));
  }
}

// Sweeps on two threads take edges in any order: the relations are those of one thread.
TEST(XmpvoEdgeSweep, SameRelationsOnOneAndTwoThreads) {
  const Scene s = dataset("helix", {{"cells", "3000"}});
  int64_t swapped = 0;
  for (int v = 0; v < 4; ++v) {
    const Camera view = fibonacci_view(s.bounds(), 14, v, ViewOptions{160, 160});
    Relations one, two;
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
      one = relations(s, view, true);
    }
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
      two = relations(s, view, true);
    }
    EXPECT_EQ(one.pairs, two.pairs) << "view " << v;
    swapped += one.stats.sweep_swaps;
  }
  EXPECT_GT(swapped, 0);
}

// The queries' one bound per query for the projected side tests (Worker::orient_raw)
// decides only signs uv_side decides the same way: the same relations, and the same counts
// of side tests decided by the filter and left to the exact predicate, with and without it
// (one thread: a thread's sweeps reuse its last start, so the counts follow the split).
TEST(XmpvoEdgeSweep, QuickSidesDecideAsTheFilter) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  for (const char* name : {"helix", "zoo", "gap", "touching-shifted", "touching-rotated", "touching-edge", "offset",
                           "slivers", "edge-on"}) {
    SCOPED_TRACE(name);
    const Scene s = std::string(name) == "helix" ? dataset(name, {{"cells", "3000"}}) : dataset(name);
    for (int v = 0; v < 2; ++v)
      for (bool sweep : {true, false}) {
        const Camera view = fibonacci_view(s.bounds(), 5, 2 * v, ViewOptions{160, 160});
        const Relations quick = relations(s, view, sweep, true), plain = relations(s, view, sweep, false);
        EXPECT_EQ(quick.pairs, plain.pairs) << "view " << v;
        EXPECT_EQ(quick.stats.side_filtered, plain.stats.side_filtered) << "view " << v;
        EXPECT_EQ(quick.stats.side_rechecked, plain.stats.side_rechecked) << "view " << v;
        EXPECT_GT(quick.stats.side_filtered, 0);
      }
  }
}

// A point query after a sweep that ended at the point takes the sweep's last covering faces
// (Worker::run_query_after_sweep): the same relations, and the same sweeps and fallbacks,
// as gathering at every point. On generated meshes most points do; the views along the axes
// and from eyes in face planes put points on other faces' projected edges, which the
// arrangement marks so that those points gather, see the degeneracy and send the view to
// full queries as before (one thread: which points follow a sweep depends on the split).
TEST(XmpvoEdgeSweep, PointsAfterASweepAsGathered) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  struct Case {
    const char* name;
    std::map<std::string, std::string> params;
    std::vector<Camera> (*views)(const Scene&, int, int);
  };
  auto fibonacci = [](const Scene& s, int w, int h) {
    std::vector<Camera> v;
    for (int i = 0; i < 4; ++i) v.push_back(fibonacci_view(s.bounds(), 4, i, ViewOptions{w, h}));
    return v;
  };
  int64_t after_sweep = 0, fallen_back = 0, rebuilt = 0;
  for (const Case& c : std::vector<Case>{{"helix", {{"cells", "3000"}}, fibonacci},
                                         {"zoo", {}, fibonacci},
                                         {"gap", {}, fibonacci},
                                         {"touching-conforming", {}, fibonacci},
                                         {"edge-on", {{"n", "6"}}, edge_on_views},
                                         {"eye-in-plane", {}, eye_in_plane_views}}) {
    SCOPED_TRACE(c.name);
    const Scene s = dataset(c.name, c.params);
    const std::vector<Camera> views = c.views(s, 160, 160);
    for (size_t v = 0; v < views.size(); ++v) {
      const Relations ends = relations(s, views[v], true, true, true), gathered = relations(s, views[v], true, true, false);
      EXPECT_EQ(ends.pairs, gathered.pairs) << "view " << v;
      EXPECT_EQ(ends.stats.sweep_edges, gathered.stats.sweep_edges) << "view " << v;
      EXPECT_EQ(ends.stats.sweep_crossings, gathered.stats.sweep_crossings) << "view " << v;
      EXPECT_EQ(ends.stats.sweep_fallbacks, gathered.stats.sweep_fallbacks) << "view " << v;
      EXPECT_EQ(ends.stats.degenerate, gathered.stats.degenerate) << "view " << v;
      EXPECT_EQ(gathered.stats.sweep_end_queries, 0);
      after_sweep += ends.stats.sweep_end_queries;
      fallen_back += gathered.stats.sweep_crossings == 0 && gathered.stats.vertex_queries > 0;
      rebuilt += ends.stats.arrangement_rebuilt;
    }
  }
  EXPECT_GT(after_sweep, 0);
  EXPECT_GT(fallen_back, 0);
  EXPECT_GT(rebuilt, 0);  // conforming views that fell back: the arrangement built again
}

// Point b of a front tetrahedron projects exactly onto the edge (c, d) of one behind it,
// and b's edge from a crosses an edge of a third one, so a sweep ends at b. Only b's own
// query can see the degeneracy: the arrangement marks b on (c, d)'s line, b gathers, and
// the view falls back to full queries as it does without the sweeps' end lists.
TEST(XmpvoEdgeSweep, PointOnAnotherEdgeAfterASweepStillGathers) {
  CellMesh m;
  m.points = {{0, 0, 0},  {4, 0, 0},  {2.3, 3, 0},   {1.7, 1, -2},     // c, d and two more
              {0, -1, -3}, {4, -1, -3}, {2.4, -1.6, -4}, {1.6, -0.5, -3.5},  // crossing (a, b) at y = -1
              {2, -2, 1.5}, {1, -0.7, 2}, {3, -1.3, 2.5}, {2, 0, 1}};      // a, two more, b
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.add_cell(CellType::Tetra, {4, 5, 6, 7});
  m.add_cell(CellType::Tetra, {8, 9, 10, 11});
  const Scene s = Scene::from_mesh("point-on-edge", m);
  Camera view;
  view.ortho = true;
  view.eye = {2, -0.5, 10}, view.target = {2, -0.5, 0}, view.up = {0, 1, 0};
  view.ortho_height = 8, view.width = view.height = 64;
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const Relations ends = relations(s, view, true, true, true), gathered = relations(s, view, true, true, false);
  EXPECT_EQ(gathered.stats.sweep_crossings, 0);  // b's full query saw the degeneracy
  EXPECT_EQ(ends.stats.sweep_crossings, 0);
  EXPECT_EQ(ends.pairs, gathered.pairs);
  EXPECT_EQ(ends.stats.vertex_queries, gathered.stats.vertex_queries);
}

// The swaps' search for the two faces of a crossed edge: in lanes and one face at a time,
// the first place of each, or n where it is not listed, over every list length up to three
// lane widths and every place (a face is listed once in a sweep's list).
TEST(XmpvoEdgeSweep, FirstOfTwoFindsBothFacesInLanesAndOneAtATime) {
  std::mt19937 rng(7);
  for (int32_t n = 0; n <= 48; ++n) {
    std::vector<int32_t> l(static_cast<size_t>(n));
    std::iota(l.begin(), l.end(), 100);
    std::shuffle(l.begin(), l.end(), rng);
    for (int32_t p0 = 0; p0 <= n; ++p0)
      for (int32_t p1 : {0, n / 2, n - 1, n}) {
        if (p1 < 0) continue;
        const int32_t g0 = p0 < n ? l[p0] : 7, g1 = p1 < n ? l[p1] : 8;  // 7, 8: listed nowhere
        for (const bool lanes : {false, true}) {
          int32_t i0 = -1, i1 = -1;
          xmpvo::detail::first_of_two(l.data(), n, g0, g1, i0, i1, lanes);
          EXPECT_EQ(i0, p0) << "n " << n << " lanes " << lanes;
          EXPECT_EQ(i1, p1) << "n " << n << " lanes " << lanes;
        }
      }
  }
}
