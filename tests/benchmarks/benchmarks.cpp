// vob_benchmarks: the radix sort against std::sort and std::stable_sort on 1M random
// (float key, int32 id) pairs (HAVS Table 1's setting), and the cell orderers on a
// ~1M-cell tet block (55^3 cubes x 6 tets) from one view. items/s = keys or cells.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <utility>

#include "harness/bench/registry.h"
#include "harness/sort/radix_sort.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

namespace {

const std::vector<float>& random_keys(size_t n) {
  static std::map<size_t, std::vector<float>> cache;
  auto& v = cache[n];
  if (v.empty()) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-1000.f, 1000.f);
    v.resize(n);
    for (float& k : v) k = u(rng);
  }
  return v;
}

void BM_RadixSort(benchmark::State& state) {
  const auto& src = random_keys(static_cast<size_t>(state.range(0)));
  std::vector<float> keys;
  std::vector<int32_t> ids(src.size());
  std::vector<uint64_t> scratch;
  for (auto _ : state) {
    state.PauseTiming();
    keys = src;
    for (size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int32_t>(i);
    state.ResumeTiming();
    vob::radix_sort_by_key(keys, ids, scratch);
    benchmark::DoNotOptimize(ids.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <bool kStable>
void BM_StdSort(benchmark::State& state) {
  const auto& src = random_keys(static_cast<size_t>(state.range(0)));
  std::vector<std::pair<float, int32_t>> pairs(src.size());
  const auto by_key = [](const auto& a, const auto& b) { return a.first < b.first; };
  for (auto _ : state) {
    state.PauseTiming();
    for (size_t i = 0; i < src.size(); ++i) pairs[i] = {src[i], static_cast<int32_t>(i)};
    state.ResumeTiming();
    if (kStable)
      std::stable_sort(pairs.begin(), pairs.end(), by_key);
    else
      std::sort(pairs.begin(), pairs.end(), by_key);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// 107,000: about the exterior faces (SXMPVO) or cells (MPVONC) of the 1M helix.
BENCHMARK(BM_RadixSort)->Arg(107000)->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_StdSort, false)->Name("BM_StdSort")->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_StdSort, true)->Name("BM_StdStableSort")->Arg(1 << 20)->Unit(benchmark::kMillisecond);

const vob::Scene& block_scene() {
  static const vob::Scene scene = vob::Scene::from_mesh("tet-block-55", vob::testing::tet_block(55, 55, 55));
  return scene;
}

void BM_Orderer(benchmark::State& state, const char* spec) {
  const vob::Scene& scene = block_scene();
  auto orderer = vob::make_orderer(spec);
  vob::PhaseClock prep;
  const vob::Scene own = scene.fresh();  // every orderer pays for its derived structures
  orderer->prepare(own, prep);
  const vob::Camera view = vob::fibonacci_view(scene.bounds(), 14, 0);
  vob::PhaseClock phases;
  for (auto _ : state) {
    vob::PhaseClock clock;
    auto o = orderer->order(view, clock);
    benchmark::DoNotOptimize(o.order.data());
    for (const auto& [name, s] : clock.phases()) phases.add(name, s);
  }
  const double n = static_cast<double>(scene.num_primitives());
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
  for (const auto& [name, s] : phases.phases())
    state.counters["ms " + name] = 1e3 * s / static_cast<double>(state.iterations());
  state.counters["cells"] = n;
  state.counters["MB held"] = static_cast<double>(orderer->bytes()) / 1e6;
}

BENCHMARK_CAPTURE(BM_Orderer, centroid_view, "centroid:key=view")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orderer, centroid_eye, "centroid")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orderer, vtk_centroid, "vtk-centroid")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orderer, vtk_centroid_one_chunk, "vtk-centroid:chunk=2147483647")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orderer, mpvo, "mpvo")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orderer, mpvonc, "mpvonc")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
