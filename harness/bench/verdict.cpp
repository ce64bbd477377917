#include "harness/bench/verdict.h"

#include "harness/scene/input_error.h"

namespace vob {

bool Verdict::input_fault() const { return order_result().input_fault(); }

nlohmann::json Verdict::json() const {
  nlohmann::json j = result.to_json();
  j["judged"] = composited ? "composited" : "order";
  return j;
}

nlohmann::json Verdict::cell_order_json() const {
  if (!cell_order) return nullptr;
  nlohmann::json j = cell_order->to_json();
  j["judged"] = "derived cell order";
  return j;
}

Verdict judge(Orderer& orderer, const std::string& spec, const Scene& scene, const Camera& view,
              const Ordering& ordering, const OracleOptions& opt, const std::string& supersample_option) {
  Verdict v;
  v.composited = orderer.claims().composites;
  if (!v.composited) {
    v.result = check_ordering(scene, view, ordering.order, opt);
    return v;
  }
  if (opt.supersample > 1)
    throw InputError(supersample_option, std::to_string(opt.supersample),
                     "'" + spec + "' composites its own image at the pixel centres and is judged " +
                         "on that; use supersample 1");
  OracleOptions order_opt = opt;
  order_opt.violation_mask = false;  // the map shows the composited verdict
  v.cell_order = check_ordering(scene, view, ordering.order, order_opt);
  v.result = orderer.composited_verdict(view, opt.violation_mask);
  return v;
}

ShownImages shown_images(Orderer& orderer, const Scene& scene, const Camera& view, const Ordering& ordering) {
  ShownImages s;
  if (orderer.claims().composites) {
    orderer.composited_images(view, s.ordered, s.exact);
  } else {
    s.ordered = render_in_order(scene, view, ordering.order);
    s.exact = render_exact(scene, view);
  }
  return s;
}

}  // namespace vob
