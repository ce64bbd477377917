// The test every exact cell orderer shares (xmpvo, bsp-xmpvo, sxmpvo): over a 14-view set
// it gives a complete order with no cycle and no violation, where a heuristic control may
// fail; the plugin's own counter checks are passed in.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "harness/bench/registry.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

namespace vob::test {

// One orderer prepared once on a fresh copy of the scene, then ordering view after view
// (as a benchmark run does).
struct ReusedOrderer {
  std::unique_ptr<Orderer> o;
  ReusedOrderer(const Scene& s, const std::string& spec) : o(make_orderer(spec)) {
    PhaseClock c;
    o->prepare(s.fresh(), c);
  }
  Ordering order(const Camera& v) {
    PhaseClock c;
    return o->order(v, c);
  }
};

struct ExactViews {
  int w = 200, h = 200;
  bool ortho = false;
  int supersample = 1;   // the oracle's S for the exact orderer
  std::string control;   // an orderer whose violations (at the pixel centres) are counted, or ""
};

// Every view of the 14-view set: `spec` orders all cells, with no cycle and zero violating
// fragments at opt.supersample, and `check(ordering, view index)` passes. Returns the number
// of views in which the control violates.
inline int expect_exact_views(const std::string& spec, const Scene& s, const ExactViews& opt,
                              const std::function<void(const Ordering&, int)>& check) {
  ReusedOrderer p(s, spec);
  std::unique_ptr<ReusedOrderer> c =
      opt.control.empty() ? nullptr : std::make_unique<ReusedOrderer>(s, opt.control);
  OracleOptions oracle;
  oracle.supersample = opt.supersample;
  int control_failures = 0;
  for (int v = 0; v < 14; ++v) {
    ViewOptions vo{opt.w, opt.h};
    vo.ortho = opt.ortho;
    const Camera view = fibonacci_view(s.bounds(), 14, v, vo);
    const Ordering r = p.order(view);
    EXPECT_TRUE(is_permutation_of(r.order, s.mesh().num_cells()));
    const OracleResult o = check_ordering(s, view, r.order, oracle);
    EXPECT_EQ(o.violating_fragments, 0) << s.name() << " view " << v << ": " << o.to_json().dump();
    EXPECT_EQ(r.cycles.cycles, 0) << s.name() << " view " << v;
    check(r, v);
    if (c && !check_ordering(s, view, c->order(view).order).ok()) ++control_failures;
  }
  return control_failures;
}

}  // namespace vob::test
