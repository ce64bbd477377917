// Every registered orderer on every small test scene of its kind from the dataset registry
// (the hard cases, the cycle scenes among them, and a small instance of each generator),
// judged against its own claims, as pbrt-v4's tests loop over every implementation:
//   - a complete permutation at every view;
//   - image_exact: no oracle violation at S = 1 on every acyclic scene, under the sampling
//     rule the claim is made for (claims.image_exact_under: gl for GL backends; there the
//     oracle's verdict, which lets violations on cycles of llvmpipe's depths pass; a view
//     whose snapped cells overlap has no exact order and is not judged, and a scene with no
//     other view is skipped, saying so);
//   - object_exact: none at S = 4 either;
//   - detects_cycles: the cycle scenes report a cycle (for an orderer that is not exact,
//     those whose cycle runs through shared faces; see face_connected);
//   - the views before do not matter: the first view, ordered again after the others by
//     the same prepared orderer, gets the same order (storage kept from frame to frame
//     must not carry a view's state into the next).
// No orderer or dataset is named here: a new registration is tested as soon as it exists.
// A configuration whose claims differ from the default's (a choice parameter such as
// backend=software) is tested as an orderer of its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/input_error.h"

using namespace vob;

namespace {

constexpr int kViews = 14;
constexpr int kSize = 48;

// Small parameters for generators that are not hard cases (those are small by default).
// Real data (skull, surface-*, tet-*) is left to its own tests: it is large or slow to mesh.
const std::map<std::string, std::map<std::string, std::string>>& generator_sizes() {
  static const std::map<std::string, std::map<std::string, std::string>> m = {
      {"gap", {{"nx", "4"}, {"ny", "4"}, {"nz", "6"}, {"gaps", "2"}}},
      {"helix", {{"cells", "1500"}, {"turns", "2"}}},
      {"sphere", {{"subdiv", "1"}}},
      {"spheres", {{"subdiv", "1"}}},
      {"block", {{"nx", "12"}, {"ny", "12"}, {"nz", "12"}}},
      {"shells", {{"nx", "12"}, {"ny", "12"}, {"nz", "12"}}},
      {"sparse", {{"nx", "16"}, {"ny", "16"}, {"nz", "16"}, {"blobs", "8"}}},
  };
  return m;
}

// The cycle hard cases are named so ("cycle", "cycle-sticks"): the one thing this test takes
// from a name, because a scene's cyclicity is not something the registry records.
bool is_cycle_scene(const std::string& dataset) { return dataset.rfind("cycle", 0) == 0; }

// True when every cell is reachable from every other through shared faces. Face arrows are
// the relations every cycle-detecting orderer builds (Claims::detects_cycles: "among the
// relations it builds"), and a cycle scene made of one such component ("cycle") has its
// cycle there; one of separate pieces ("cycle-sticks") has it only among relations that
// an exact orderer must find.
bool face_connected(const Scene& scene) {
  const MeshFaces& f = scene.faces();
  std::vector<int32_t> parent(scene.num_primitives());
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = int32_t(i);
  auto root = [&](int32_t x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  };
  for (size_t i = 0; i < f.num_faces(); ++i)
    if (f.cell1[i] >= 0) parent[size_t(root(f.cell0[i]))] = root(f.cell1[i]);
  for (size_t i = 0; i < parent.size(); ++i)
    if (root(int32_t(i)) != root(0)) return false;
  return true;
}

struct Case {
  std::string spec;     // orderer spec: "xmpvo" or "stencil-layers:backend=software"
  DatasetSpec dataset;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.spec << " on " << c.dataset.label(); }

bool same(const Claims& a, const Claims& b) {
  return a.object_exact == b.object_exact && a.image_exact == b.image_exact &&
         a.image_exact_under == b.image_exact_under && a.detects_cycles == b.detects_cycles &&
         a.composites == b.composites;
}

// The default configuration of every orderer, plus each choice value that changes its claims.
std::vector<std::string> configurations(const OrdererInfo& info) {
  std::vector<std::string> out = {info.name};
  const Claims def = make_orderer(info.name)->claims();
  for (const ParamSpec& p : info.params)
    if (p.kind == ParamSpec::Kind::Choice)
      for (const std::string& c : p.choices) {
        const std::string spec = info.name + ":" + p.name + "=" + c;
        if (!same(make_orderer(spec)->claims(), def)) out.push_back(spec);
      }
  return out;
}

std::vector<Case> all_cases() {
  std::vector<DatasetSpec> scenes;
  for (const auto& d : dataset_registry()) {
    DatasetSpec s;
    s.name = d.name;
    const auto it = generator_sizes().find(d.name);
    if (it != generator_sizes().end())
      s.set = it->second;
    else if (!d.hard_case)
      continue;
    scenes.push_back(s);
  }
  std::vector<Case> out;
  for (const auto& info : orderer_registry())
    for (const std::string& spec : configurations(info))
      for (const DatasetSpec& s : scenes)
        if (find_dataset(s.name).kind == info.kind) out.push_back({spec, s});
  return out;
}

class Conformance : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(Conformance, CompleteAndTrueToItsClaims) {
  const Case& c = GetParam();
  const Scene scene = make_scene(c.dataset);
  std::unique_ptr<PreparedOrderer> p;
  try {
    p = std::make_unique<PreparedOrderer>(prepare_orderer(c.spec, scene));
  } catch (const InputError& e) {
    // Only an OpenGL backend may be unavailable (no context); anything else is a failure.
    if (resolved_parameters(c.spec).value("backend", "") == "gl") GTEST_SKIP() << e.what();
    throw;
  }
  const Claims claims = p->orderer->claims();
  const bool acyclic = !is_cycle_scene(c.dataset.name);
  const bool exact = claims.image_exact || claims.object_exact;
  const auto views = dataset_views(c.dataset, scene, kViews, {}, kSize, kSize, false, 1.0);
  ASSERT_FALSE(views.empty());
  int64_t cycles = 0, covered = 0;
  int unjudged = 0;  // gl rule: views whose snapped cells overlap (no order is exact there)
  std::optional<std::pair<int, Camera>> first_view;  // the first view ordered, and its order
  std::vector<int32_t> first_order;
  const RasterRule claim_rule = claims.object_exact ? RasterRule::exact : claims.image_exact_under;
  std::string unjudged_why;
  for (const auto& [vi, cam] : views) {
    const std::string where = c.spec + " on " + c.dataset.label() + " view " + std::to_string(vi);
    FrameMeasurement m;
    try {
      m = measure_frame(*p, cam, 0, 1);
    } catch (const InputError& e) {
      // A view GL would clip (an eye inside the model) is outside the gl rule
      // (raster_rule.h): an orderer working under it refuses the view, saying so.
      if (!(exact && claim_rule == RasterRule::gl)) throw;
      ++unjudged, unjudged_why = "view " + std::to_string(vi) + ": " + e.what();
      continue;
    }
    ASSERT_NO_THROW(check_complete(scene, m.ordering, c.spec)) << where;
    if (!first_view) first_view = {vi, cam}, first_order = m.ordering.order;
    EXPECT_FALSE(m.repeats.back().empty()) << where << ": no timed phase";
    for (int32_t id : m.ordering.cycles.primitives)
      EXPECT_TRUE(id >= 0 && size_t(id) < scene.num_primitives()) << where;
    if (acyclic && exact) {
      OracleOptions rule;  // the sampling rule the claim is made under (GL backends: gl)
      rule.raster = claim_rule;
      const OracleResult r = check_ordering(scene, cam, m.ordering.order, rule);
      if (r.input_fault() && rule.raster == RasterRule::gl) {
        // Snapping inverted cells thinner than its grid: the snapped mesh has a true cycle.
        ++unjudged, unjudged_why = "view " + std::to_string(vi) + ": " + std::to_string(r.overlapping_pairs) +
                                   " overlapping pairs";
        continue;
      }
      ASSERT_FALSE(r.input_fault()) << where << ": the test scene itself is invalid";
      covered += r.covered_pixels;
      // gl: violations on cycles of the rule's own depths pass, as few as any order has
      // (rule_cycles.h); under the exact rule ok() means no violation at all.
      EXPECT_TRUE(r.ok()) << where << " S=1: " << r.to_json().dump();
    }
    cycles += m.ordering.cycles.cycles;
    if (claims.composites) {
      // One verdict: a compositing orderer answers for what it composited at this view.
      OracleOptions opt;
      opt.violation_mask = true;
      const Verdict v = judge(*p->orderer, c.spec, scene, cam, m.ordering, opt, "supersample");
      EXPECT_EQ(v.json().at("judged"), "composited") << where;
      EXPECT_EQ(v.result.samples, int64_t(cam.width) * cam.height) << where;
      EXPECT_LE(v.result.violating_pixels, v.result.covered_pixels) << where;
      EXPECT_EQ(std::count(v.result.violation_mask.begin(), v.result.violation_mask.end(), uint8_t(1)),
                v.result.violating_pixels) << where;
      EXPECT_TRUE(v.cell_order.has_value()) << where;
    }
    if (acyclic && claims.object_exact) {
      OracleOptions opt;
      opt.supersample = 4;
      const OracleResult r = check_ordering(scene, cam, m.ordering.order, opt);
      EXPECT_EQ(r.violating_fragments, 0) << where << " S=4: " << r.to_json().dump();
    }
  }
  if (first_view) {
    const FrameMeasurement again = measure_frame(*p, first_view->second, 0, 1);
    EXPECT_TRUE(again.ordering.order == first_order)
        << c.spec << " on " << c.dataset.label() << " view " << first_view->first
        << ": a different order when ordered again after the other views";
  }
  EXPECT_GT(p->orderer->bytes(), 0u) << c.spec;
  if (acyclic && exact && unjudged == int(views.size()))
    GTEST_SKIP() << c.spec << " on " << c.dataset.label() << ": no view at " << kSize << "x" << kSize
                 << " can be judged under the gl rule: snapped cells that overlap, or triangles GL would clip (last: " << unjudged_why << ")";
  if (acyclic && exact) {
    // An exactness check over views that see nothing would pass vacuously.
    EXPECT_GT(covered, 0) << c.spec << " on " << c.dataset.label() << ": the views must see the scene";
    EXPECT_EQ(cycles, 0) << c.spec << " on " << c.dataset.label()
                         << ": an exact orderer found a cycle in an acyclic scene";
  }
  if (!acyclic && claims.detects_cycles && (exact || face_connected(scene))) {
    EXPECT_GT(cycles, 0) << c.spec << " on " << c.dataset.label() << " reports no cycle";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryOrdererEveryScene, Conformance, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           std::string s = i.param.spec + "_on_" + i.param.dataset.name;
                           for (char& ch : s)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return s;
                         });

// The loop must reach every kind of scene and the cycle scenes, or its claims checks are
// vacuous for a whole family.
TEST(ConformanceCases, EveryOrdererHasScenesAndCycleScenesAreIncluded) {
  const auto cases = all_cases();
  for (const auto& info : orderer_registry()) {
    int n = 0;
    for (const Case& c : cases) n += c.spec == info.name;
    EXPECT_GE(n, 2) << info.name << " has no test scenes of its kind";
  }
  int cycle_cases = 0;
  for (const Case& c : cases) cycle_cases += is_cycle_scene(c.dataset.name);
  EXPECT_GT(cycle_cases, 0);
}
