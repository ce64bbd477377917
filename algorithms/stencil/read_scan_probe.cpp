// Probe stencil-read-scan (stencil_probes.h): Krishnan et al.'s Fig. 2 measurement.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/stencil/stencil_layers.h"
#include "algorithms/stencil/stencil_probes.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

struct Variant {
  std::string label, backend, variant;
  int block = 0;  // blocked only
};

// The paper's variants (naive, blocked 32 and 64) on OpenGL, and naive against blocked 64
// on the software backend (the same passes without OpenGL).
const std::vector<Variant>& variants() {
  static const std::vector<Variant> v = {{"gl naive", "gl", "naive"},
                                         {"gl blocked 32", "gl", "blocked", 32},
                                         {"gl blocked 64", "gl", "blocked", 64},
                                         {"software naive", "software", "naive"},
                                         {"software blocked 64", "software", "blocked", 64}};
  return v;
}

Params variant_params(const Variant& v) {
  Params p("stencil-layers");
  p.set("backend", v.backend);
  p.set("variant", v.variant);
  if (v.block) p.set("block", std::to_string(v.block));
  return p;
}

std::unique_ptr<Orderer> make_variant(const Variant& v) {
  Params p = variant_params(v);
  auto o = make_from_info(stencil_layers_orderer_info(), p);
  p.check_all_used();
  return o;
}

// Every declared parameter of the variant with its effective value (as records show them).
nlohmann::json variant_parameters(const Variant& v) {
  Params p = variant_params(v);
  return resolve_params(stencil_layers_orderer_info().params, p).values();
}

nlohmann::json run(Params& params, const ProbeContext& ctx) {
  if (params.dry_run()) return nlohmann::json::object();  // no parameters to check
  if (ctx.views.empty()) throw InputError("stencil-read-scan", ctx.dataset_label, "the suite gives no views");
  const auto& vs = variants();
  std::vector<std::unique_ptr<Orderer>> orderers;
  for (const Variant& v : vs) {
    orderers.push_back(make_variant(v));
    PhaseClock prep;
    orderers.back()->prepare(*ctx.scene, prep);
    for (int w = 0; w < ctx.warmup; ++w) {
      PhaseClock c;
      orderers.back()->order(ctx.views.front().second, c);
    }
  }
  struct Sum {
    std::vector<std::pair<std::string, double>> phases;  // in first-seen order
    double total = 0, pixels_read = 0, layers = 0;
  };
  std::vector<Sum> sums(vs.size());
  const int repeats = std::max(1, ctx.repeats);
  for (size_t f = 0; f < ctx.views.size(); ++f) {
    if (ctx.progress)
      ctx.progress("  view " + std::to_string(f + 1) + "/" + std::to_string(ctx.views.size()));
    for (size_t i = 0; i < vs.size(); ++i) {
      PhaseClock best;
      Ordering o;
      for (int r = 0; r < repeats; ++r) {
        PhaseClock c;
        o = orderers[i]->order(ctx.views[f].second, c);
        if (r == 0 || c.total() < best.total()) best = c;
      }
      Sum& s = sums[i];
      for (const auto& [name, sec] : best.phases()) {
        bool found = false;
        for (auto& p : s.phases)
          if (p.first == name) p.second += sec, found = true;
        if (!found) s.phases.emplace_back(name, sec);
      }
      s.total += best.total();
      s.pixels_read += o.counters.at("pixels_read");
      s.layers += o.counters.at("layers");
    }
  }
  const double frames = double(ctx.views.size());
  nlohmann::json out{{"frames", ctx.views.size()},
                     {"repeats", repeats},
                     {"warmup", ctx.warmup},
                     {"w", ctx.views.front().second.width},
                     {"h", ctx.views.front().second.height}};
  nlohmann::json list = nlohmann::json::array();
  for (size_t i = 0; i < vs.size(); ++i) {
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, sec] : sums[i].phases) phases[name] = sec;
    list.push_back({{"label", vs[i].label},
                    {"parameters", variant_parameters(vs[i])},
                    {"seconds", sums[i].total},
                    {"phases", phases},
                    {"pixels_read_per_frame", sums[i].pixels_read / frames},
                    {"layers_per_frame", sums[i].layers / frames}});
  }
  out["variants"] = list;
  return out;
}

}  // namespace

ProbeInfo stencil_read_scan_probe_info() {
  return {"stencil-read-scan",
          "Krishnan et al. Fig. 2: render/read/scan seconds of the layer extraction, naive against "
          "blocked (32, 64) on OpenGL and the software backend, variants interleaved per view",
          true, run};
}

}  // namespace vob
