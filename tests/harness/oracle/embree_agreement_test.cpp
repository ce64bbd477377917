// The rasterizer's per-sample cell sequences against Embree's, on generated meshes and 14
// views (see harness/oracle/sequences.h for the tolerance and the grazing rule).
#include <gtest/gtest.h>

#include "harness/oracle/embree_caster.h"
#include "harness/oracle/sequences.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

namespace {

struct Case {
  const char* name;
  CellMesh mesh;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"tet block 4", test::kuhn_block(4)});
  c.push_back({"jittered tet block 5", test::kuhn_block(5, 1.0, 0.2, 11)});
  c.push_back({"hex block 3", test::hex_block(3)});
  return c;
}

void check_views(const Case& c, bool ortho, int supersample, int size) {
  validate_cell_mesh(c.mesh, c.name);
  const Scene s = Scene::from_mesh(c.name, c.mesh);
  const double tol = 1e-5 * s.bounds().radius();
  const EmbreeCaster caster(s);
  ViewOptions vo;
  vo.width = vo.height = size;
  vo.ortho = ortho;
  int64_t grazing = 0, compared = 0, segments = 0;
  for (const Camera& cam : fibonacci_views(s.bounds(), 14, vo)) {
    const CellSequences a = raster_cell_sequences(s, cam, supersample);
    const CellSequences b = caster.cast(cam, supersample);
    const SequenceComparison cmp = compare_sequences(a, b, tol);
    EXPECT_EQ(cmp.mismatched, 0) << c.name << (ortho ? " ortho" : " perspective") << " view "
                                 << cam.to_json().dump() << "\n" << cmp.to_json().dump(1);
    grazing += cmp.grazing;
    compared += cmp.samples;
    segments += int64_t(a.segments.size());
  }
  EXPECT_GT(segments, compared / 4);  // the meshes fill a good part of the views
  // Grazing rays are rare: a ray must pass within about tol of an edge.
  EXPECT_LT(grazing, compared / 1000 + 5);
  std::printf("%s %s S=%d: %lld samples, %lld segments, %lld grazing, 0 mismatched\n", c.name,
              ortho ? "ortho" : "perspective", supersample, (long long)compared,
              (long long)segments, (long long)grazing);
}

}  // namespace

TEST(EmbreeAgreement, PerspectiveViews) {
  for (const Case& c : cases()) check_views(c, false, 1, 64);
}

TEST(EmbreeAgreement, OrthographicViews) {
  for (const Case& c : cases()) check_views(c, true, 1, 64);
}

TEST(EmbreeAgreement, Supersampled) {
  const std::vector<Case> cs = cases();
  check_views(cs[1], false, 2, 40);
}

TEST(EmbreeAgreement, EyeInsideTheMesh) {
  // Perspective rays start inside a cell; orthographic rays start on an eye plane that cuts
  // through the mesh. Both sources clip to t >= 0.
  const CellMesh m = test::kuhn_block(3, 1.0, 0.2, 5);
  const Scene s = Scene::from_mesh("inside", m);
  const EmbreeCaster caster(s);
  const double tol = 1e-5 * s.bounds().radius();
  for (bool ortho : {false, true}) {
    const Camera cam = test::test_camera({1.37, 1.61, 1.52}, {2.9, 0.3, 0.8}, 48, 48, ortho, 2.5);
    const CellSequences a = raster_cell_sequences(s, cam, 1);
    const SequenceComparison cmp = compare_sequences(a, caster.cast(cam, 1), tol);
    EXPECT_EQ(cmp.mismatched, 0) << cmp.to_json().dump(1);
    EXPECT_EQ(cmp.samples, 48 * 48);
    int64_t from_zero = 0;
    for (const RaySegment& r : a.segments) from_zero += r.t_in == 0;
    EXPECT_GT(from_zero, ortho ? 100 : 48 * 48 - 1);
  }
}

TEST(EmbreeAgreement, ComparisonDetectsDifferentSequences) {
  // Not vacuous: sequences of two different views disagree, and a dropped cell is caught.
  const CellMesh m = test::kuhn_block(3);
  const Scene s = Scene::from_mesh("block", m);
  const EmbreeCaster caster(s);
  ViewOptions vo;
  vo.width = vo.height = 32;
  const double tol = 1e-5 * s.bounds().radius();
  const Camera c0 = fibonacci_view(s.bounds(), 14, 0, vo), c1 = fibonacci_view(s.bounds(), 14, 1, vo);
  EXPECT_GT(compare_sequences(raster_cell_sequences(s, c0, 1), caster.cast(c1, 1), tol).mismatched, 100);
  CellSequences a = raster_cell_sequences(s, c0, 1);
  const CellSequences b = caster.cast(c0, 1);
  ASSERT_EQ(compare_sequences(a, b, tol).mismatched, 0);
  for (RaySegment& r : a.segments) r.cell = r.cell == 7 ? 8 : r.cell;  // relabel one cell
  EXPECT_GT(compare_sequences(a, b, tol).mismatched, 0);
  EXPECT_THROW(compare_sequences(a, caster.cast(c0, 2), tol), InputError);
}
