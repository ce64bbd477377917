// The centroid orderer's per-frame kernel (keys from the centroids, then the sort into ids)
// on the ~1M centroids of a 55^3 x 6 tet block: the fused argsort (RadixArgsort) against the
// old path (a key pass into KeySort, its four-histogram 8-bit radix sort, then a copy), both
// keys, at 1 and 2 threads (tbb::global_control; the old path is serial). items/s = cells.
// BM_CentroidPeer: whole order() calls of centroid, centroid:key=view and vtk-centroid on
// the same block at 1 and 2 threads, process CPU time and real time: the centroid / vtk
// ratio of issue 16 within one run of one binary (build it before and after a change).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <vector>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/scene/scene.h"
#include "harness/sort/radix_argsort.h"
#include "harness/sort/radix_sort.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

namespace {

struct Setup {
  std::vector<vob::Vec3> centroids;
  vob::Camera view;
};

const Setup& setup() {
  static const Setup s = [] {
    const vob::Scene scene = vob::Scene::from_mesh("tet-block-55", vob::testing::tet_block(55, 55, 55));
    return Setup{scene.cell_centroids().points, vob::fibonacci_view(scene.bounds(), 14, 0)};
  }();
  return s;
}

// range(0): 0 = eye-distance key, 1 = view-depth key.
template <class F>
void with_key(const benchmark::State& state, F&& f) {
  const Setup& s = setup();
  const vob::Vec3* c = s.centroids.data();
  const vob::Vec3 eye = s.view.eye, fwd = s.view.forward();
  if (state.range(0) == 1)
    f([=](size_t i) { return dot(c[i] - eye, fwd); });
  else
    f([=](size_t i) { return length(c[i] - eye); });
}

void BM_CentroidKeySortOld(benchmark::State& state) {
  const size_t n = setup().centroids.size();
  vob::KeySort sort;
  with_key(state, [&](auto key) {
    for (auto _ : state) {
      sort.resize(n);
      for (size_t i = 0; i < n; ++i) {
        sort.keys[i] = static_cast<float>(-key(i));
        sort.ids[i] = static_cast<int32_t>(i);
      }
      sort.sort();
      std::vector<int32_t> out = sort.ids;
      benchmark::DoNotOptimize(out.data());
    }
  });
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}

// range(1): the thread limit.
void BM_CentroidKeySortFused(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<size_t>(state.range(1)));
  const size_t n = setup().centroids.size();
  vob::RadixArgsort sort;
  with_key(state, [&](auto key) {
    for (auto _ : state) {
      std::vector<int32_t> out(n);
      sort.sort(n, [&](size_t i) { return vob::float_sort_key(static_cast<float>(-key(i))); }, out.data());
      benchmark::DoNotOptimize(out.data());
    }
  });
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
  state.counters["passes"] = sort.passes();
  state.counters["blocks"] = sort.blocks();
}

BENCHMARK(BM_CentroidKeySortOld)
    ->ArgNames({"view"})
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CentroidKeySortFused)
    ->ArgNames({"view", "threads"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 2})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The keys and the sort apart on the 1M helix of centroid-peer-1m-t1.json, per view of its
// 3 (view 1 spans 22 bits of float depth, views 0 and 2 span 23: issue 16), one thread.
// range(0): view, range(1): 0 = eye-distance key, 1 = view-depth key, range(2): 0 = time
// the keys, 1 = time the sort (the keys made outside the timing).
void BM_CentroidHelixSort(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
  static const vob::Scene scene = [] {
    vob::Params p("helix");
    p.set("cells", "1003520");
    p.set("faces", "41472");
    return vob::make_dataset("helix", p);
  }();
  const std::vector<vob::Vec3>& cs = scene.cell_centroids().points;
  const vob::Vec3* c = cs.data();
  const vob::Camera view = vob::fibonacci_view(scene.bounds(), 3, static_cast<int>(state.range(0)));
  const vob::Vec3 eye = view.eye, fwd = view.forward();
  const bool by_view = state.range(1) == 1, time_sort = state.range(2) == 1;
  const size_t n = cs.size();
  vob::RadixArgsort sort;
  std::vector<int32_t> out(n);
  const auto keys = [&] {
    if (by_view) sort.make_keys(n, [=](size_t i) { return vob::float_sort_key(static_cast<float>(-dot(c[i] - eye, fwd))); });
    else sort.make_keys(n, [=](size_t i) { return vob::float_sort_key(static_cast<float>(-length(c[i] - eye))); });
  };
  for (auto _ : state) {
    if (time_sort) {
      state.PauseTiming();
      keys();
      state.ResumeTiming();
      sort.sort_keys(out.data());
    } else {
      keys();
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["passes"] = sort.passes();
}
BENCHMARK(BM_CentroidHelixSort)
    ->ArgNames({"view", "viewkey", "sort"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

// range(0): the thread limit.
void BM_CentroidPeer(benchmark::State& state, const char* spec) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<size_t>(state.range(0)));
  static const vob::Scene scene = vob::Scene::from_mesh("tet-block-55", vob::testing::tet_block(55, 55, 55));
  auto orderer = vob::make_orderer(spec);
  vob::PhaseClock prep;
  const vob::Scene own = scene.fresh();
  orderer->prepare(own, prep);
  const vob::Camera view = vob::fibonacci_view(scene.bounds(), 14, 0);
  for (auto _ : state) {
    vob::PhaseClock clock;
    auto o = orderer->order(view, clock);
    benchmark::DoNotOptimize(o.order.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(scene.num_primitives()));
}

BENCHMARK_CAPTURE(BM_CentroidPeer, centroid, "centroid")
    ->ArgNames({"threads"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_CentroidPeer, centroid_view, "centroid:key=view")
    ->ArgNames({"threads"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_CentroidPeer, vtk_centroid, "vtk-centroid")
    ->ArgNames({"threads"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
