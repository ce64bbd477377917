// SXMPVO against MPVONC frame by frame, phase by phase, on a generated helix at 512x512
// with one thread (issue 16: the ratio and SXMPVO's phase III, per exterior face). Each
// benchmark prepares the orderer once and times order() for view `view` of 14; the
// counters are the mean seconds of each phase over the timed frames (phase names shortened
// to their number: "III" is SXMPVO's scan, MPVONC's DFS) and phase III per exterior face.
// range(0): the orderer (see kSpecs), range(1): the view, range(2): the helix (kHelices: the
// 1M-cell helix with its default exterior, and cook-table4's 1.5M-cell one).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <map>
#include <memory>
#include <string>

#include "harness/bench/registry.h"
#include "harness/view/view_set.h"
#include "datasets/datasets.h"

namespace {

const char* const kSpecs[] = {"sxmpvo", "mpvonc", "sxmpvo:renumber=false", "mpvonc:renumber=false"};
const char* const kHelices[][2] = {{"1000000", ""}, {"1485000", "59500"}};

const vob::Scene& helix(int which) {
  static std::map<int, vob::Scene> cache;
  auto it = cache.find(which);
  if (it == cache.end()) {
    vob::Params p("helix");
    p.set("cells", kHelices[which][0]);
    if (*kHelices[which][1]) p.set("faces", kHelices[which][1]);
    it = cache.emplace(which, vob::make_dataset("helix", p)).first;
  }
  return it->second;
}

void BM_HelixFrame(benchmark::State& state) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const vob::Scene& scene = helix(static_cast<int>(state.range(2)));
  const std::string spec = kSpecs[state.range(0)];
  state.SetLabel(spec);
  std::unique_ptr<vob::Orderer> orderer = vob::make_orderer(spec);
  vob::PhaseClock prep;
  orderer->prepare(scene, prep);
  const vob::Camera view = vob::fibonacci_view(scene.bounds(), 14, static_cast<int>(state.range(1)),
                                               vob::ViewOptions{512, 512});
  vob::PhaseClock clock;
  double faces = 0;
  for (auto _ : state) {
    vob::Ordering o = orderer->order(view, clock);
    benchmark::DoNotOptimize(o.order.data());
    if (o.counters.count("exterior_faces")) faces = o.counters.at("exterior_faces");
  }
  const double n = static_cast<double>(state.iterations());
  for (const auto& [name, seconds] : clock.phases()) {
    const std::string number = name.substr(0, name.find(' '));
    state.counters[number] = seconds / n;
    if (number == "III" && faces > 0) state.counters["III_ns_per_face"] = seconds / n / faces * 1e9;
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(scene.mesh().num_cells()));
}

BENCHMARK(BM_HelixFrame)
    ->ArgNames({"orderer", "view", "helix"})
    ->ArgsProduct({{0, 1, 2, 3}, {0, 4, 9}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
