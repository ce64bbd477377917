// XMPVO's arrangement: a view's projected edges are set_faces' edges of all faces with
// the kept ones (facing != 0), exactly the lists a sort of the kept faces' edge keys gives,
// whether every face is kept or some are seen edge-on, and in any order of such views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/arrangement.h"
#include "datasets/datasets.h"
#include "datasets/generators/view_cases.h"
#include "harness/cpu_features.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::xmpvo;
using namespace vob::test;

namespace {

// The edge lists by a sort of the kept faces' keys: (points, smaller first), then the face
// signed -1 - f where it has the edge the other way round.
struct Lists {
  std::vector<std::pair<int32_t, int32_t>> edges;
  std::vector<int32_t> off, faces;
  std::vector<int8_t> dir;
};

Lists sorted_lists(const ExteriorFaces& ext, const Projection& proj) {
  std::vector<std::tuple<int32_t, int32_t, int32_t>> keys;
  for (int32_t f : proj.kept)
    for (int k = 0, n = ext.size[f]; k < n; ++k) {
      int32_t a = ext.vertex[4 * f + k], b = ext.vertex[4 * f + (k + 1) % n];
      const bool flip = a > b;
      if (flip) std::swap(a, b);
      keys.emplace_back(a, b, flip ? -1 - f : f);
    }
  std::sort(keys.begin(), keys.end());
  Lists l;
  l.off.push_back(0);
  for (size_t k = 0; k < keys.size(); ++k) {
    const auto [a, b, f] = keys[k];
    if (k == 0 || std::get<0>(keys[k - 1]) != a || std::get<1>(keys[k - 1]) != b) {
      l.edges.emplace_back(a, b);
      l.off.push_back(l.off.back());
    }
    l.faces.push_back(f < 0 ? -1 - f : f);
    l.dir.push_back(f < 0 ? -1 : 1);
    ++l.off.back();
  }
  return l;
}

// The scene's exterior faces projected for `view`, as the orderer projects them.
void project(const Scene& s, const Camera& view, Signs& signs, Projection& proj) {
  signs.g = ViewGeometry::of(view);
  const Aabb box = s.mesh().bounds();
  proj.run(s.exterior_faces(), view, signs, box.center(), box.radius());
}

// Builds the arrangement of `view` and compares its edge lists; returns the faces not kept.
size_t expect_sorted_lists(Arrangement& arr, const Scene& s, const Camera& view) {
  const ExteriorFaces& ext = s.exterior_faces();
  Signs signs;
  Projection proj;
  project(s, view, signs, proj);
  arr.build(ext, proj, signs);
  const Lists want = sorted_lists(ext, proj);
  EXPECT_EQ(arr.edges, want.edges);
  EXPECT_EQ(arr.edge_face_off, want.off);
  EXPECT_EQ(arr.edge_faces, want.faces);
  EXPECT_EQ(arr.edge_face_dir, want.dir);
  return ext.face.size() - proj.kept.size();
}

}  // namespace

TEST(XmpvoArrangement, EdgesOfTheKeptFacesInAnyOrderOfViews) {
  const Scene s = dataset("edge-on", {{"n", "3"}});
  const std::vector<Camera> edge_on = edge_on_views(s, 64, 64);
  ASSERT_GE(edge_on.size(), 2u);
  const Camera general = fibonacci_view(s.bounds(), 6, 1, ViewOptions{64, 64});
  Arrangement arr;
  arr.set_faces(s.exterior_faces());
  // All kept, then some seen edge-on, then all again, then edge-on twice in a row.
  EXPECT_EQ(expect_sorted_lists(arr, s, general), 0u);
  EXPECT_GT(expect_sorted_lists(arr, s, edge_on[0]), 0u);
  EXPECT_EQ(expect_sorted_lists(arr, s, general), 0u);
  EXPECT_GT(expect_sorted_lists(arr, s, edge_on[1]), 0u);
  EXPECT_GT(expect_sorted_lists(arr, s, edge_on.back()), 0u);
  EXPECT_EQ(expect_sorted_lists(arr, s, general), 0u);
}

TEST(XmpvoArrangement, BuildBeforeSetFacesIsRefused) {
  const Scene s = dataset("helix", {{"cells", "600"}});
  const Camera view = fibonacci_view(s.bounds(), 6, 1, ViewOptions{64, 64});
  Signs signs;
  Projection proj;
  project(s, view, signs, proj);
  Arrangement arr;
  EXPECT_THROW(arr.build(s.exterior_faces(), proj, signs), std::logic_error);
}

namespace {
// sort_edge_crossings' contract: by key, equal keys in their order in the input, reversed
// first when the first key exceeds the last.
std::vector<EdgeCrossing> reference_sort(std::vector<EdgeCrossing> v) {
  if (!v.empty() && v.front().key > v.back().key) std::reverse(v.begin(), v.end());
  std::stable_sort(v.begin(), v.end(), [](const EdgeCrossing& a, const EdgeCrossing& b) { return a.key < b.key; });
  return v;
}

std::vector<int32_t> vertices_of(const std::vector<EdgeCrossing>& v) {
  std::vector<int32_t> out;
  for (const EdgeCrossing& c : v) out.push_back(c.vertex);
  return out;
}
}  // namespace

// Lists short enough to be sorted by counting places and longer ones, with distinct keys,
// ties (which the counted places cannot order) and nearly sorted runs either way.
TEST(XmpvoArrangement, EdgeCrossingsSortLikeAStableSort) {
  uint64_t seed = 12345;
  auto next = [&] { return seed = seed * 6364136223846793005ull + 1442695040888963407ull, seed >> 33; };
  for (int32_t n : {0, 1, 2, 3, 5, 24, 63, 64, 65, 200})
    for (int kind = 0; kind < 4; ++kind) {
      std::vector<EdgeCrossing> v(n);
      for (int32_t i = 0; i < n; ++i) {
        const double noise = static_cast<double>(next() % 1000) / 100.0;
        const double key = kind == 0 ? static_cast<double>(next() % 100000)   // distinct, mostly
                           : kind == 1 ? static_cast<double>(next() % 4)      // many ties
                           : kind == 2 ? i + noise                            // nearly sorted
                                       : n - i + noise;                       // nearly reversed
        v[i] = {key, 0.0, i, 0};
      }
      std::vector<EdgeCrossing> got;
      sort_edge_crossings(v.data(), n, got);
      EXPECT_EQ(vertices_of(got), vertices_of(reference_sort(v))) << "n " << n << " kind " << kind;
    }
}

// A NaN key has no place among the others: the list is still a permutation of its records.
TEST(XmpvoArrangement, EdgeCrossingsWithANanKeyStayAPermutation) {
  std::vector<EdgeCrossing> v;
  for (int32_t i = 0; i < 9; ++i) v.push_back({i == 4 ? NAN : 9.0 - i, 0.0, i, 0});
  std::vector<EdgeCrossing> got;
  sort_edge_crossings(v.data(), static_cast<int32_t>(v.size()), got);
  std::vector<int32_t> ids = vertices_of(got);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<int32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

// On a helix every crossing sits on both its edges once; each edge's list, sorted, is in
// order along the edge (keys increasing).
TEST(XmpvoArrangement, EachEdgeHoldsItsCrossingsByKey) {
  const Scene s = dataset("helix", {{"cells", "20000"}});
  const Camera view = fibonacci_view(s.bounds(), 6, 1, ViewOptions{256, 256});
  const ExteriorFaces& ext = s.exterior_faces();
  Signs signs;
  Projection proj;
  project(s, view, signs, proj);
  Arrangement arr;
  arr.set_faces(ext);
  arr.build(ext, proj, signs);
  const size_t crossings = arr.vertices.size() - arr.projected_vertices;
  ASSERT_GT(crossings, 1000u);
  std::vector<int> seen(arr.vertices.size(), 0);
  std::vector<EdgeCrossing> sorted;
  for (size_t e = 0; e + 1 < arr.edge_vertex_off.size(); ++e) {
    const int32_t x0 = arr.edge_vertex_off[e];
    sort_edge_crossings(&arr.edge_crossings[x0], arr.edge_vertex_off[e + 1] - x0, sorted);
    for (size_t x = 0; x < sorted.size(); ++x) {
      const EdgeCrossing& c = sorted[x];
      const ArrVertex& v = arr.vertices[c.vertex];
      EXPECT_TRUE(v.e1 == static_cast<int32_t>(e) || v.e2 == static_cast<int32_t>(e));
      EXPECT_TRUE(c.other == (v.e1 == static_cast<int32_t>(e) ? v.e2 : v.e1));
      ++seen[c.vertex];
      if (x > 0) {
        EXPECT_LE(sorted[x - 1].key, c.key) << "edge " << e;
      }
    }
  }
  for (size_t v = arr.projected_vertices; v < arr.vertices.size(); ++v) EXPECT_EQ(seen[v], 2) << "vertex " << v;
  EXPECT_EQ(arr.edge_crossings.size(), 2 * crossings);
}

namespace {
// The lane kinds each test runs against the scalar pass: AVX2's two passes, and where the
// CPU has it AVX-512's single pass.
std::vector<bool> avx512_kinds() { return cpu_has_avx512() ? std::vector<bool>{false, true} : std::vector<bool>{false}; }

// The same crossings, in the same order, with the same counts of pairs decided and left to
// the exact test.
void expect_same_arrangement(const Arrangement& lanes, const Arrangement& scalar, const std::string& what) {
  ASSERT_EQ(lanes.vertices.size(), scalar.vertices.size()) << what;
  for (size_t v = 0; v < lanes.vertices.size(); ++v) {
    const ArrVertex &x = lanes.vertices[v], &y = scalar.vertices[v];
    EXPECT_TRUE(x.a == y.a && x.b == y.b && x.c == y.c && x.d == y.d && x.e1 == y.e1 && x.e2 == y.e2 &&
                x.t == y.t && x.box.x0 == y.box.x0 && x.box.y0 == y.box.y0 && x.box.x1 == y.box.x1 &&
                x.box.y1 == y.box.y1)
        << what << " vertex " << v;
  }
  EXPECT_EQ(lanes.crossings_filtered, scalar.crossings_filtered) << what;
  EXPECT_EQ(lanes.crossings_rechecked, scalar.crossings_rechecked) << what;
}

// The arrangement built by AVX2's passes and, where the CPU has it, by AVX-512's single pass,
// each compared with `scalar`, built from the same faces and projection (its build returned
// `candidates`).
void expect_lanes_match(const ExteriorFaces& ext, const Projection& proj, Signs& signs, const Arrangement& scalar,
                        int64_t candidates, const std::string& what) {
  for (const bool wide : avx512_kinds()) {
    Arrangement lanes;
    lanes.lanes_avx512 = wide;
    lanes.unswept_sheet = scalar.unswept_sheet;
    lanes.set_faces(ext);
    const std::string which = what + (wide ? " avx512" : " avx2");
    EXPECT_EQ(lanes.build(ext, proj, signs), candidates) << which;
    expect_same_arrangement(lanes, scalar, which);
  }
}
}  // namespace

// The double filter in lanes and one pair at a time find the same crossings.
// Views along the axes of structured blocks put many pairs' corners on the lines between
// buckets, where the lanes' first pass asks the bucket's own column and row.
TEST(XmpvoArrangement, LanesMatchTheScalarPassOnBucketSides) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  for (const auto& [name, params] : std::vector<std::pair<std::string, std::map<std::string, std::string>>>{
           {"edge-on", {{"n", "6"}}}, {"edge-on", {{"n", "9"}}}, {"eye-in-plane", {}}}) {
    const Scene s = dataset(name, params);
    const ExteriorFaces& ext = s.exterior_faces();
    const std::vector<Camera> views = name == "edge-on" ? edge_on_views(s, 128, 128) : eye_in_plane_views(s, 128, 128);
    for (size_t vi = 0; vi < views.size(); ++vi) {
      Signs signs;
      Projection proj;
      project(s, views[vi], signs, proj);
      Arrangement scalar;
      scalar.lanes = false;
      scalar.set_faces(ext);
      const int64_t candidates = scalar.build(ext, proj, signs);
      expect_lanes_match(ext, proj, signs, scalar, candidates, name + " view " + std::to_string(vi));
    }
  }
}

// With and without the unswept front sheet (whose inner edges' pairs the lanes drop
// themselves).
TEST(XmpvoArrangement, FilterLanesMatchTheScalarFilter) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> scenes = {
      {"helix", {{"cells", "20000"}}}, {"touching-shifted", {}}, {"touching-rotated", {}},
      {"gap", {}}, {"slivers", {}}, {"edge-on", {{"n", "3"}}}};
  for (const auto& [name, params] : scenes) {
    const Scene s = dataset(name, params);
    const ExteriorFaces& ext = s.exterior_faces();
    for (const auto& [vi, sheet] : std::vector<std::pair<int, int>>{{0, 0}, {5, 0}, {11, 0}, {0, 1}, {5, 1}}) {
      const Camera view = fibonacci_view(s.bounds(), 14, vi, ViewOptions{256, 256});
      Signs signs;
      Projection proj;
      project(s, view, signs, proj);
      Arrangement scalar;
      scalar.lanes = false;
      scalar.unswept_sheet = sheet;
      scalar.set_faces(ext);
      const int64_t candidates = scalar.build(ext, proj, signs);
      expect_lanes_match(ext, proj, signs, scalar, candidates,
                         name + " view " + std::to_string(vi) + " sheet " + std::to_string(sheet));
    }
  }
}

// A crossing whose pair's common lower corner lies just left of a column line (just below a
// row line), within Arrangement::kSideBand of the next bucket's side: both edges lie in
// that bucket too, where the pair loop must ask the grid and leave the pair to the bucket
// owning its corner. Every pass finds such a crossing once, the same way. No scene puts a
// corner there by itself (the lines fall between lattice points), so one is planted: the
// exterior point whose box side lies nearest a line is moved, across the view, until its
// box side lies half the band short of the line.
TEST(XmpvoArrangement, CornersJustShortOfABucketSideAreFoundOnce) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  const Scene s = dataset("helix", {{"cells", "5000"}});
  const Camera view = fibonacci_view(s.bounds(), 14, 3, ViewOptions{256, 256});
  const Aabb bounds = s.mesh().bounds();
  for (const int axis : {0, 1}) {  // 0: a column line (the boxes' left sides), 1: a row line
    const std::string along = axis == 0 ? "column line" : "row line";
    ExteriorFaces ext = s.exterior_faces();
    Signs signs;
    Projection proj;
    auto reproject = [&] {
      signs.g = ViewGeometry::of(view);
      proj.run(ext, view, signs, bounds.center(), bounds.radius());
    };
    reproject();
    Arrangement first;
    first.set_faces(ext);
    first.build(ext, proj, signs);
    const BucketGrid grid = first.grid();
    const double side = axis == 0 ? grid.cw : grid.ch, band = Arrangement::kSideBand * side;
    auto low = [&](int32_t p) { return axis == 0 ? proj.point_box(p).x0 : proj.point_box(p).y0; };
    auto high = [&](int32_t p) { return axis == 0 ? proj.point_box(p).x1 : proj.point_box(p).y1; };
    auto line_above = [&](double x) {
      return axis == 0 ? grid.gx0 + (grid.col(x) + 1) * grid.cw : grid.gy0 + (grid.row(x) + 1) * grid.ch;
    };
    // Candidates: the points used, nearest a line first (the smallest move).
    std::vector<std::pair<double, int32_t>> near_line;
    for (size_t p = 0; p < ext.points.size(); ++p) {
      if (!proj.point_used[p]) continue;
      const double x = low(static_cast<int32_t>(p)), up = line_above(x);
      near_line.push_back({std::min(up - x, x - (up - side)), static_cast<int32_t>(p)});
    }
    std::sort(near_line.begin(), near_line.end());
    const Vec3 across = axis == 0 ? view.right() : view.true_up();
    bool planted = false;
    for (size_t k = 0; k < near_line.size() && k < 40 && !planted; ++k) {
      const int32_t p = near_line[k].second;
      const Vec3 home = ext.points[p];
      const double x = low(p), up = line_above(x);
      const double line = up - x < x - (up - side) ? up : up - side;
      const double want = line - 0.5 * band;
      // Secant steps along `across` until the box side lies within the band short of the line.
      auto move_to = [&](double t) {  // the point and the face corners it is
        ext.points[p] = home + across * t;
        for (size_t f = 0; f < ext.face.size(); ++f)
          for (int j = 0; j < ext.size[f]; ++j)
            if (ext.vertex[4 * f + j] == p) ext.corners[4 * f + j] = ext.points[p];
        reproject();
        return low(p);
      };
      double t0 = 0, x0 = x, t1 = 1e-3 * bounds.radius(), x1 = move_to(t1);
      for (int i = 0; i < 20 && !(x1 < line && x1 >= line - band); ++i) {
        if (x1 == x0) break;
        const double t2 = t1 + (want - x1) * (t1 - t0) / (x1 - x0);
        t0 = t1, x0 = x1, t1 = t2, x1 = move_to(t1);
      }
      if (!(x1 < line && x1 >= line - band)) {
        move_to(0);
        continue;
      }
      Arrangement scalar;
      scalar.lanes = false;
      scalar.set_faces(ext);
      const int64_t candidates = scalar.build(ext, proj, signs);
      const BucketGrid& g = scalar.grid();
      const bool same_grid = g.gw == grid.gw && g.gh == grid.gh && g.gx0 == grid.gx0 && g.gy0 == grid.gy0 &&
                             g.cw == grid.cw && g.ch == grid.ch;
      // The crossings whose corner is planted: its side within the band short of the line, and
      // both edges' boxes reaching past the line (so both lie in the next bucket too).
      size_t corners = 0;
      std::map<std::pair<int32_t, int32_t>, int> pairs;
      for (size_t v = scalar.projected_vertices; v < scalar.vertices.size(); ++v) {
        const ArrVertex& w = scalar.vertices[v];
        ++pairs[{std::min(w.e1, w.e2), std::max(w.e1, w.e2)}];
        double corner = -INFINITY, reach = INFINITY;
        for (const int32_t e : {w.e1, w.e2}) {
          const auto [a, b] = scalar.edges[e];
          corner = std::max(corner, std::min(low(a), low(b)));
          reach = std::min(reach, std::max(high(a), high(b)));
        }
        corners += corner < line && corner >= line - band && reach >= line;
      }
      if (!same_grid || corners == 0) {
        move_to(0);
        continue;
      }
      planted = true;
      for (const auto& [pair, count] : pairs) EXPECT_EQ(count, 1) << along << ": edges " << pair.first << ", " << pair.second;
      expect_lanes_match(ext, proj, signs, scalar, candidates, along + " point " + std::to_string(p));
    }
    EXPECT_TRUE(planted) << "no crossing's corner could be put just short of a " << along;
  }
}
