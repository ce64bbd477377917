#include "harness/cli/experiments/measure.h"

#include <algorithm>
#include <cstdio>

#include "datasets/datasets.h"
#include "harness/bench/runner.h"
#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"

namespace vob {

using json = nlohmann::json;

Scene make(const Ds& d) {
  Params p(d.name);
  for (const auto& [k, v] : d.set) p.set(k, v);
  std::fprintf(stderr, "generating %s\n", d.label.c_str());
  return make_dataset(d.name, p);
}

std::vector<Camera> views(const Scene& s, int count, int w, int h) {
  std::vector<Camera> out;
  const std::vector<Camera> all = fibonacci_views(s.bounds(), 14, ViewOptions{w, h});
  for (int i = 0; i < count; ++i) out.push_back(all[i * 14 / count]);
  return out;
}

AlgoRun run_algo(const std::string& spec, const Scene& scene, const std::vector<Camera>& cams,
                 int warmup, int repeats, bool oracle) {
  AlgoRun r;
  PreparedOrderer p = prepare_orderer(spec, scene);
  r.ran = true;
  r.prepare = p.prepare_seconds;
  for (const auto& [name, s] : p.prepare_clock.phases()) r.prepare_phases[name] += s;
  for (const Camera& cam : cams) {
    const FrameMeasurement m = measure_frame(p, cam, warmup, repeats);
    check_complete(scene, m.ordering, spec);
    r.total += m.total_median();
    const json phases = m.phases_json();
    for (const auto& [name, v] : phases.items()) r.phases[name] += v["median"].get<double>();
    for (const auto& [name, v] : m.ordering.counters) r.counters[name] += v;
    r.cycles += m.ordering.cycles.cycles;
    if (oracle) {
      const OracleResult o = check_ordering(scene, cam, m.ordering.order);
      r.violating_views += !o.ok();
      r.violating_fragments += o.violating_fragments;
    }
  }
  r.views = static_cast<int>(cams.size());
  const double k = 1.0 / std::max<size_t>(cams.size(), 1);
  r.total *= k;
  for (auto& [_, v] : r.phases) v *= k;
  for (auto& [_, v] : r.counters) v *= k;
  r.bytes = static_cast<double>(p.orderer->bytes());
  std::fprintf(stderr, "  %-12s %-22s prepare %8.3f s  %9.4f s/frame%s\n", spec.c_str(), scene.name().c_str(),
               r.prepare, r.total, oracle ? (r.violating_views ? "  VIOLATIONS" : "  oracle ok") : "");
  return r;
}

}  // namespace vob
