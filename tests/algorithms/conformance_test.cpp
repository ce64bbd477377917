// Every registered orderer of kind cells, on small built meshes: a complete permutation
// without duplicates on convex, disconnected and cyclic scenes; cycles reported by the
// orderers that claim to report them; bad parameters rejected with InputError.
#include <gtest/gtest.h>

#include <regex>

#include "harness/bench/registry.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;
using namespace vob::testing;

namespace {

struct Case {
  Scene scene;
  std::vector<Camera> views;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  auto add = [&](const char* name, CellMesh m, std::vector<Camera> extra = {}) {
    validate_cell_mesh(m, name);
    Scene s = Scene::from_mesh(name, std::move(m));
    ViewOptions opt;
    opt.width = opt.height = 32;
    std::vector<Camera> v = fibonacci_views(s.bounds(), 3, opt);
    opt.ortho = true;
    v.push_back(fibonacci_view(s.bounds(), 3, 1, opt));
    v.insert(v.end(), extra.begin(), extra.end());
    out.push_back({s, v});
  };
  add("block", tet_block(3, 3, 3));
  add("two-blocks", two_blocks(2, 0.5));
  add("blade-ring", blade_ring(8), {ring_axis_view(false), ring_axis_view(true)});
  return out;
}

std::vector<const OrdererInfo*> cell_orderers() {
  std::vector<const OrdererInfo*> v;
  for (const auto& info : orderer_registry())
    if (info.kind == SceneKind::Cells) v.push_back(&info);
  return v;
}

}  // namespace

TEST(Conformance, RegistryHasTheCellOrderers) {
  for (const char* name : {"centroid", "vtk-centroid", "mpvo", "mpvonc"})
    EXPECT_NO_THROW(find_orderer(name)) << name;
}

TEST(Conformance, EveryCellOrdererGivesACompletePermutation) {
  const auto all = cases();
  for (const OrdererInfo* info : cell_orderers()) {
    for (const Case& c : all) {
      auto orderer = make_orderer(info->name);
      EXPECT_EQ(orderer->name(), info->name);
      EXPECT_EQ(orderer->scene_kind(), SceneKind::Cells);
      PhaseClock prep;
      const Scene scene = c.scene.fresh();  // outlives the orderer's use, as in the runner
      orderer->prepare(scene, prep);
      for (size_t v = 0; v < c.views.size(); ++v) {
        PhaseClock clock;
        const Ordering o = orderer->order(c.views[v], clock);
        EXPECT_TRUE(is_permutation_of(o.order, c.scene.num_primitives()))
            << info->name << " on " << c.scene.name() << " view " << v;
        EXPECT_FALSE(clock.phases().empty()) << info->name;
        for (int32_t m : o.cycles.primitives)
          EXPECT_TRUE(m >= 0 && static_cast<size_t>(m) < c.scene.num_primitives()) << info->name;
      }
      EXPECT_GT(orderer->bytes(), 0u) << info->name;
    }
  }
}

TEST(Conformance, CycleReportingOrderersReportTheBladeRing) {
  Scene ring = Scene::from_mesh("blade-ring", blade_ring(8));
  for (const OrdererInfo* info : cell_orderers()) {
    auto orderer = make_orderer(info->name);
    if (!orderer->claims().detects_cycles) continue;
    PhaseClock prep;
    const Scene scene = ring.fresh();
    orderer->prepare(scene, prep);
    for (bool ortho : {false, true}) {
      PhaseClock clock;
      const Ordering o = orderer->order(ring_axis_view(ortho), clock);
      EXPECT_TRUE(is_permutation_of(o.order, ring.num_primitives())) << info->name;
      EXPECT_GE(o.cycles.cycles, 1) << info->name << (ortho ? " ortho" : " perspective");
      EXPECT_FALSE(o.cycles.primitives.empty()) << info->name;
    }
  }
}

TEST(Conformance, ConvexAcyclicBlockHasNoCycles) {
  Scene block = Scene::from_mesh("block", tet_block(3, 3, 3));
  for (const OrdererInfo* info : cell_orderers()) {
    auto orderer = make_orderer(info->name);
    PhaseClock prep;
    const Scene scene = block.fresh();
    orderer->prepare(scene, prep);
    for (const Camera& view : fibonacci_views(block.bounds(), 4)) {
      PhaseClock clock;
      EXPECT_EQ(orderer->order(view, clock).cycles.cycles, 0) << info->name;
    }
  }
}

TEST(Conformance, UnknownParameterIsAnInputError) {
  for (const auto& info : orderer_registry())
    EXPECT_THROW(make_orderer(info.name + ":no_such_parameter=1"), InputError) << info.name;
  EXPECT_THROW(make_orderer("no-such-orderer"), InputError);
  EXPECT_THROW(make_orderer("mpvo:novalue"), InputError);
}

TEST(Conformance, BadParameterValueIsAnInputError) {
  // The first key of each documented parameter list ("key=..."), given a value no
  // parameter accepts.
  const std::regex first_key(R"(^\s*([A-Za-z_][A-Za-z0-9_]*)=)");
  int checked = 0;
  for (const auto& info : orderer_registry()) {
    std::smatch m;
    if (!std::regex_search(info.parameters, m, first_key)) continue;
    EXPECT_THROW(make_orderer(info.name + ":" + m[1].str() + "=%bogus%"), InputError)
        << info.name << " " << m[1].str();
    ++checked;
  }
  EXPECT_GE(checked, 2);  // centroid key, vtk-centroid chunk
  EXPECT_THROW(make_orderer("vtk-centroid:chunk=0"), InputError);
  EXPECT_THROW(make_orderer("centroid:key=depth"), InputError);
}
