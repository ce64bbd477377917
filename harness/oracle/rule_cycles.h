// Violations the gl sampling rule forces on every order (raster_rule.h).
//
// Under the rule a primitive's depth at a pixel is llvmpipe's (triangles: its float plane
// in 24 bits, llvmpipe_depth.h; cells: segments between snapped faces), and those depths
// can order two primitives one way at one pixel and the other way at another. The pixel
// precedence graph has an edge y -> x wherever y drawn after x at a shared pixel would
// violate (the oracle's own test: y's query key behind x's nearest key); no order meets
// every edge of a cycle. This finds the graph's strongly connected components holding two
// or more primitives (cyclic components) and splits the order's violations:
// - a violating fragment is on a cycle when every fragment drawn before it and nearer than
//   it belongs to its own cyclic component; the others are avoidable;
// - inside a cyclic component of at most kMaxExactComponent primitives, the fewest
//   violated (edge, pixel) pairs over all orders of its primitives is found by trying them
//   all; `excess` is how many more the order violates there. A larger component in which
//   the order violates anything counts in `unbounded` (no minimum is claimed for it).
// The order is as good as the rule allows when avoidable, excess and unbounded are 0.
// The graph is linear in the fragments: per pixel the nearer fragments are a prefix of the
// list sorted by key, reached through one auxiliary node per prefix.
#pragma once
#include <cstdint>

#include <nlohmann/json.hpp>

#include "harness/raster/fragments.h"

namespace vob {

constexpr int kMaxExactComponent = 7;

struct RuleCycles {
  int64_t components = 0;        // cyclic components
  int64_t primitives = 0;        // primitives in them
  int64_t largest = 0;           // primitives in the largest one
  int64_t cycle_fragments = 0;   // violating fragments on a cycle (see above)
  int64_t cycle_pixels = 0;      // violating pixels whose every violating fragment is
  int64_t avoidable_fragments = 0;
  int64_t avoidable_pixels = 0;  // violating pixels with an avoidable violating fragment
  int64_t forced_pairs = 0;      // the fewest (edge, pixel) pairs any order violates inside components
  int64_t excess = 0;            // the order's violated pairs inside components beyond that
  int64_t unbounded = 0;         // components too large for the minimum, with violations in them
  bool as_good_as_the_rule_allows() const { return avoidable_fragments == 0 && excess == 0 && unbounded == 0; }
  nlohmann::json to_json() const;
};

// The split for the order the collector draws in; `cells` selects the keys (cells: t_in
// and the segment midpoint; triangles: the 24-bit depth in Fragment::t_out).
RuleCycles find_rule_cycles(const FragmentCollector& collector, bool cells);

}  // namespace vob
