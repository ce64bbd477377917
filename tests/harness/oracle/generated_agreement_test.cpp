// The oracle's fragments and the Embree caster agree on every generated cell mesh: the gap,
// helix and zoo generators, a TetGen mesh and every hard case, over their views (the hard
// cases' own cameras where they have them, else 14 Fibonacci views). Grazing samples (rays
// within a hair of an edge) and rays lying in a face plane (the axis-aligned views of
// edge-on and cycle-sticks; see sequences.h) are allowed; mismatches are not.
#include <gtest/gtest.h>

#include <cstdio>

#include "datasets/datasets.h"
#include "harness/bench/runner.h"
#include "harness/oracle/embree_caster.h"
#include "harness/oracle/sequences.h"

using namespace vob;

namespace {
struct Generated {
  std::string name;
  std::map<std::string, std::string> set;
};
void PrintTo(const Generated& g, std::ostream* os) { *os << g.name; }

std::vector<Generated> generated() {
  std::vector<Generated> out = {{"gap", {{"nx", "5"}, {"ny", "4"}, {"nz", "9"}, {"gaps", "2"}}},
                                {"helix", {{"cells", "3000"}}},
                                {"zoo", {}},
                                {"tet-hand", {}}};
  for (const auto& d : dataset_registry())
    if (d.hard_case && d.kind == SceneKind::Cells) out.push_back({d.name, {}});
  return out;
}
class Agreement : public ::testing::TestWithParam<Generated> {};
}  // namespace

TEST_P(Agreement, RasterAndEmbreeSequencesMatch) {
  const Generated g = GetParam();
  DatasetSpec spec;
  spec.name = g.name;
  spec.set = g.set;
  const Scene scene = make_scene(spec);
  const double tol = 1e-5 * scene.bounds().radius();
  const EmbreeCaster caster(scene);
  int64_t samples = 0, grazing = 0, in_plane = 0, mismatched = 0, covered = 0;
  for (const auto& [vi, cam] : dataset_views(spec, scene, 14, {}, 96, 80, false, 1.0)) {
    const CellSequences a = raster_cell_sequences(scene, cam, 1);
    const SequenceComparison cmp = compare_sequences(a, caster.cast(cam, 1), tol, 5,
                                                     ray_in_face_plane_test(scene, cam, 1, tol));
    EXPECT_EQ(cmp.mismatched, 0) << g.name << " view " << vi << "\n" << cmp.to_json().dump(1);
    samples += cmp.samples;
    grazing += cmp.grazing;
    in_plane += cmp.in_plane;
    mismatched += cmp.mismatched;
    for (int64_t s = 0; s < a.num_samples(); ++s) covered += a.at(s).empty() ? 0 : 1;
  }
  EXPECT_GT(covered, 0) << g.name << ": the views must see the mesh";
  std::printf("%s: %lld samples, %lld covered, %lld grazing, %lld in a face plane, %lld mismatched\n",
              g.name.c_str(), (long long)samples, (long long)covered, (long long)grazing,
              (long long)in_plane, (long long)mismatched);
}

INSTANTIATE_TEST_SUITE_P(EveryGeneratedMesh, Agreement, ::testing::ValuesIn(generated()),
                         [](const ::testing::TestParamInfo<Generated>& i) {
                           std::string s = i.param.name;
                           for (char& c : s)
                             if (!isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });
