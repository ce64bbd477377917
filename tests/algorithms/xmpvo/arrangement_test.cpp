// XMPVO's arrangement: a view's projected edges are set_faces' edges of all faces with
// the kept ones (facing != 0), exactly the lists a sort of the kept faces' edge keys gives,
// whether every face is kept or some are seen edge-on, and in any order of such views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "algorithms/xmpvo/arrangement.h"
#include "datasets/datasets.h"
#include "datasets/generators/view_cases.h"
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

// Builds the arrangement of `view` and compares its edge lists; returns the faces not kept.
size_t expect_sorted_lists(Arrangement& arr, const Scene& s, const Camera& view) {
  const ExteriorFaces& ext = s.exterior_faces();
  Signs signs;
  signs.g = ViewGeometry::of(view);
  Projection proj;
  const Aabb box = s.mesh().bounds();
  proj.run(ext, view, signs, box.center(), box.radius());
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
  signs.g = ViewGeometry::of(view);
  Projection proj;
  const Aabb box = s.mesh().bounds();
  proj.run(s.exterior_faces(), view, signs, box.center(), box.radius());
  Arrangement arr;
  EXPECT_THROW(arr.build(s.exterior_faces(), proj, signs), std::logic_error);
}
