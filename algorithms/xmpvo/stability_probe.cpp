#include "algorithms/xmpvo/stability_probe.h"

#include "algorithms/xmpvo/xmpvo.h"
#include "harness/bench/ordering_check.h"
#include "harness/oracle/oracle.h"

namespace vob {
namespace {

using json = nlohmann::json;

Ordering order_once(const std::string& predicates, const Scene& scene, const Camera& cam) {
  Params p("xmpvo");
  p.set("predicates", predicates);
  auto o = make_from_info(xmpvo_orderer_info(), p);
  PhaseClock prep, clock;
  const Scene fresh = scene.fresh();  // lives while the orderer does: it may keep references
  o->prepare(fresh, prep);
  Ordering out = o->order(cam, clock);
  check_complete(scene, out, "xmpvo:predicates=" + predicates);
  return out;
}

// One view: both orders, the compare-mode counters, both oracle verdicts.
json study_view(const Scene& scene, const Camera& cam) {
  const Ordering exact = order_once("compare", scene, cam);
  const Ordering plain = order_once("double", scene, cam);
  const auto& k = exact.counters;
  const OracleResult oe = check_ordering(scene, cam, exact.order);
  const OracleResult od = check_ordering(scene, cam, plain.order);
  return {{"arrows", static_cast<double>(scene.faces().num_faces())},
          {"facing", k.at("facing_decisions")},
          {"crossings", k.at("crossing_decisions")},
          {"sides", k.at("side_decisions")},
          {"disagree_arrows", k.at("disagree_arrows")},
          {"disagree_facing", k.at("disagree_facing")},
          {"disagree_crossings", k.at("disagree_crossing")},
          {"disagree_sides", k.at("disagree_side")},
          {"exact_violating_pixels", oe.violating_pixels},
          {"double_violating_pixels", od.violating_pixels},
          {"exact_failing_views", int(!oe.ok())},
          {"double_failing_views", int(!od.ok())},
          {"exact_cycles", exact.cycles.cycles},
          {"double_cycles", plain.cycles.cycles},
          {"undecided", k.at("depth_undecided")}};
}

json run(Params& params, const ProbeContext& ctx) {
  if (params.dry_run()) return json::object();
  json total = json::object(), per_view = json::array();
  for (const auto& [vi, cam] : ctx.views) {
    json v = study_view(*ctx.scene, cam);
    for (const auto& [name, value] : v.items())
      total[name] = total.value(name, 0.0) + value.get<double>();
    v["view_index"] = vi;
    per_view.push_back(v);
    if (ctx.progress)
      ctx.progress("view " + std::to_string(vi) + ": violating pixels exact " +
                   v["exact_violating_pixels"].dump() + ", double " + v["double_violating_pixels"].dump());
  }
  total["views"] = per_view.size();
  if (!ctx.views.empty())
    total["size"] = std::to_string(ctx.views[0].second.width) + "x" + std::to_string(ctx.views[0].second.height);
  total["per_view"] = per_view;
  return total;
}

}  // namespace

ProbeInfo xmpvo_stability_probe_info() {
  return {"xmpvo-stability",
          "XMPVO's double against exact sign decisions and the oracle verdict of both orders, per view",
          true, run};
}

}  // namespace vob
