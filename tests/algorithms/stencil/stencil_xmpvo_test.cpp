// stencil-xmpvo: with the software backend exact at the pixel centres (the oracle at S = 1
// finds nothing) on nonconvex and disconnected meshes where MPVONC fails, with the same
// relations that consecutive layers give at each pixel; with the GL backend on the same
// views; cycles reported.
#include <gtest/gtest.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::testing;

TEST(StencilXmpvo, ExactAtPixelCentresWhereMpvoncFails) {
  const std::vector<Scene> scenes = {
      dataset("gap", {{"nx", "6"}, {"ny", "6"}, {"nz", "12"}, {"gaps", "3"}}),
      dataset("helix", {{"cells", "3000"}, {"turns", "2"}}),
      Scene::from_mesh("two-blocks", two_blocks(2, 0.5))};
  int mpvonc_failures = 0;
  for (const Scene& s : scenes) {
    double relations = 0;
    for (int v = 0; v < 8; ++v) {
      const Camera view = fibonacci_view(s.bounds(), 8, v, ViewOptions{96, 96});
      const Outcome r = run_checked("stencil-xmpvo:backend=software", s, view);
      EXPECT_TRUE(is_permutation_of(r.ordering.order, s.num_primitives()));
      EXPECT_EQ(r.oracle.violating_fragments, 0) << s.name() << " view " << v << " "
                                                 << r.oracle.to_json().dump();
      const auto& k = r.ordering.counters;
      EXPECT_EQ(k.at("unclassified_faces"), 0) << s.name() << " view " << v;
      EXPECT_EQ(k.at("exterior_faces"), double(s.faces().boundary.size()));
      EXPECT_GE(k.at("layers"), 2);
      relations += k.at("relations");
      // The pairs of consecutive layers at each pixel are SXMPVO's PIX-list pairs.
      const Outcome sx = run_checked("sxmpvo", s, view);
      EXPECT_EQ(k.at("relations"), sx.ordering.counters.at("pn_relations")) << s.name() << " view " << v;
      mpvonc_failures += !run_checked("mpvonc", s, view).oracle.ok();
      // OpenGL on the same view: the same counters exist, the order is complete.
      const Outcome g = run_checked("stencil-xmpvo:backend=gl,variant=naive", s, view);
      EXPECT_TRUE(is_permutation_of(g.ordering.order, s.num_primitives()));
      EXPECT_EQ(g.ordering.counters.at("exterior_faces"), k.at("exterior_faces"));
    }
    if (s.name() != "helix") {
      EXPECT_GT(relations, 0) << s.name();
    }
  }
  EXPECT_GT(mpvonc_failures, 0);  // the scenes need the exterior-face relations
}

TEST(StencilXmpvo, CyclesAreReportedAndBroken) {
  const Scene ring = Scene::from_mesh("blade-ring", blade_ring(8));
  for (const char* spec : {"stencil-xmpvo:backend=software", "stencil-xmpvo:backend=gl"}) {
    for (bool ortho : {false, true}) {
      const Outcome r = run_checked(spec, ring, ring_axis_view(ortho));
      EXPECT_TRUE(is_permutation_of(r.ordering.order, ring.num_primitives()));
      EXPECT_GE(r.ordering.cycles.cycles, 1) << spec;
    }
  }
}
