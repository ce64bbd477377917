// find_edge_contacts: which exterior edges an exterior face not having them meets (the
// premise of XMPVO's comparison-free swaps). Hand-made faces for each way of meeting and
// of not meeting, and the generated scenes: conforming meshes none, touching volumes some.
#include <gtest/gtest.h>

#include "algorithms/xmpvo/edge_contacts.h"
#include "datasets/datasets.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::xmpvo;
using namespace vob::test;

namespace {

// Triangles over the given points (ids), as an ExteriorFaces holds them.
ExteriorFaces faces(std::vector<Vec3> points, const std::vector<std::array<int32_t, 3>>& tris) {
  ExteriorFaces ext;
  ext.points = std::move(points);
  for (const auto& t : tris) {
    ext.face.push_back(static_cast<int32_t>(ext.face.size()));
    ext.size.push_back(3);
    ext.cell.push_back(0);
    ext.vertex.insert(ext.vertex.end(), {t[0], t[1], t[2], -1});
  }
  return ext;
}

int64_t touched(const std::vector<Vec3>& points, const std::vector<std::array<int32_t, 3>>& tris) {
  const EdgeContacts c = find_edge_contacts(faces(points, tris));
  EXPECT_TRUE(c.triangles_only);
  return c.touched_edges;
}

}  // namespace

TEST(EdgeContacts, FacesMeetingOnlyAtSharedVerticesAndEdgesTouchNothing) {
  // Two triangles folded along a shared edge.
  EXPECT_EQ(touched({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}, {{0, 1, 2}, {1, 3, 2}}), 0);
  // A fan around one shared vertex, out of plane.
  EXPECT_EQ(touched({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 1}, {0, -1, 1}}, {{0, 1, 2}, {0, 3, 4}}), 0);
  // A flat 2x2 grid of squares, each split in two: coplanar faces with shared vertices,
  // edges on one straight line continuing each other.
  std::vector<Vec3> grid;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) grid.push_back({double(x), double(y), 0});
  std::vector<std::array<int32_t, 3>> tris;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      const int32_t a = 3 * y + x;
      tris.push_back({a, a + 1, a + 4});
      tris.push_back({a, a + 4, a + 3});
    }
  EXPECT_EQ(touched(grid, tris), 0);
  // In one plane, an edge passing a corner of the other face: no line of that face's
  // edges separates them, the edge's own line does.
  EXPECT_EQ(touched({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {3.8, -0.5, 0}, {4.5, 0.5, 0}, {5.5, -1, 0}}, {{0, 1, 2}, {3, 4, 5}}), 0);
  // Boxes overlapping, faces apart.
  EXPECT_EQ(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1.5, 1.5, 0.1}, {3, 1.5, 0.1}, {1.5, 3, 2}}, {{0, 1, 2}, {3, 4, 5}}), 0);
}

TEST(EdgeContacts, EveryWayOfMeetingAnEdgeInsideCounts) {
  // A vertex of one face on the middle of the other's edge, in its plane (a T-junction).
  EXPECT_GE(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {2, -1, 0}, {0, -1, 0}}, {{0, 1, 2}, {3, 4, 5}}), 1);
  // The same vertex from above the plane (volumes touching at a point of an edge).
  EXPECT_GE(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {2, -1, 1}, {0, -1, 1}}, {{0, 1, 2}, {3, 4, 5}}), 1);
  // An edge through a face's interior.
  EXPECT_GE(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}}, {{0, 1, 2}, {3, 4, 5}}), 1);
  // Coplanar faces overlapping (volumes touching face to face, shifted).
  EXPECT_GE(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0}, {2.5, 0.5, 0}, {0.5, 2.5, 0}}, {{0, 1, 2}, {3, 4, 5}}), 1);
  // An edge lying on a longer edge of another face (collinear overlap), one vertex shared:
  // both of those edges, and the edge from the vertex on the long edge (touching the first
  // face at its endpoint only, counted conservatively).
  EXPECT_EQ(touched({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, -1, 1}}, {{0, 1, 2}, {0, 3, 4}}), 3);
}

TEST(EdgeContacts, QuadrilateralsAreLeftToTheComparisons) {
  ExteriorFaces ext = faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  ext.size[0] = 4;
  ext.vertex[3] = 3;
  EXPECT_FALSE(find_edge_contacts(ext).triangles_only);
}

TEST(EdgeContacts, GeneratedScenes) {
  for (const char* name : {"tiny", "gap", "offset", "slivers"}) {
    const EdgeContacts c = find_edge_contacts(dataset(name).exterior_faces());
    EXPECT_TRUE(c.triangles_only) << name;
    EXPECT_GT(c.edges, 0) << name;
    EXPECT_EQ(c.touched_edges, 0) << name;
  }
  EXPECT_EQ(find_edge_contacts(dataset("helix", {{"cells", "3000"}}).exterior_faces()).touched_edges, 0);
  for (const char* name : {"touching-conforming", "touching-shifted", "touching-rotated", "touching-edge"})
    EXPECT_GT(find_edge_contacts(dataset(name).exterior_faces()).touched_edges, 0) << name;
}
