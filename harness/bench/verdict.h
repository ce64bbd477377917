// The one verdict of an orderer at a view, used by `vobench check`, the runner's records and
// the image reporter alike. An orderer that composites itself (Claims::composites, e.g.
// HAVS) is judged on what it composites (Orderer::composited_verdict); every other orderer
// by the oracle on its order. For a compositing orderer the oracle still runs on the cell
// order it returns: that count is the "derived cell order" (records' oracle_cell_order),
// and its overlapping cells are the input's fault as for any orderer.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/bench/orderer.h"
#include "harness/oracle/oracle.h"

namespace vob {

struct Verdict {
  OracleResult result;                     // THE verdict
  bool composited = false;                 // judged on what the orderer composited
  std::optional<OracleResult> cell_order;  // compositing orderers: the derived cell order's
  bool input_fault() const;                // overlapping cells (from the order's oracle run)
  const OracleResult& order_result() const { return cell_order ? *cell_order : result; }
  bool violated() const { return !result.ok() && !input_fault(); }
  // The verdict's to_json() with "judged": "composited" | "order".
  nlohmann::json json() const;
  // The derived cell order's to_json() with "judged": "derived cell order"; null for others.
  nlohmann::json cell_order_json() const;
};

// Judges the orderer's last ordering at `view` (untimed: call it outside the PhaseClock
// phases). opt.violation_mask asks for the verdict's mask. A compositing orderer judges
// its composite at the pixel centres only: opt.supersample > 1 is an InputError naming
// `supersample_option` (e.g. "--supersample").
// `spec` names the orderer in messages.
Verdict judge(Orderer& orderer, const std::string& spec, const Scene& scene, const Camera& view,
              const Ordering& ordering, const OracleOptions& opt, const std::string& supersample_option);

// The pair of images an ordering is shown by: for a compositing orderer what it composited
// and its own exact composite (Orderer::composited_images), for others render_in_order of
// the order and render_exact.
struct ShownImages {
  Image ordered, exact;
};
ShownImages shown_images(Orderer& orderer, const Scene& scene, const Camera& view, const Ordering& ordering);

}  // namespace vob
