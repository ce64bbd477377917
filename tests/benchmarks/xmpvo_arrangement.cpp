// XMPVO's arrangement (Arrangement::build: the edges' grid, the pair loop, the crossing
// vertices and their lists along each edge) side by side in one run (issue 16): the pair
// loop one pair at a time, in AVX2's two passes, and in AVX-512's single pass, on the
// 200k-cell helix at one view of 14 at 512x512, one thread. Lanes this CPU cannot run are
// skipped. range(0): the pair loop (see kLoops), range(1): the view. Counters: candidate
// pairs, crossings, and the time per candidate pair.
#include <benchmark/benchmark.h>

#include "algorithms/xmpvo/arrangement.h"
#include "datasets/datasets.h"
#include "harness/cpu_features.h"
#include "harness/view/view_set.h"

namespace {

struct Loop {
  const char* name;
  bool lanes, avx512;
  bool (*runs_here)();
};
bool always() { return true; }
const Loop kLoops[] = {{"scalar", false, false, &always},
                       {"avx2", true, false, &vob::cpu_has_avx2},
                       {"avx512", true, true, &vob::cpu_has_avx512}};

const vob::Scene& helix_200k() {
  static const vob::Scene scene = [] {
    vob::Params p("helix");
    p.set("cells", "200000");
    return vob::make_dataset("helix", p);
  }();
  return scene;
}

void BM_XmpvoArrangement(benchmark::State& state) {
  const Loop& loop = kLoops[state.range(0)];
  state.SetLabel(loop.name);
  if (!loop.runs_here()) {
    state.SkipWithError("this CPU cannot run the lanes");
    return;
  }
  const vob::Scene& scene = helix_200k();
  const vob::ExteriorFaces& ext = scene.exterior_faces();
  const vob::Camera view =
      vob::fibonacci_view(scene.bounds(), 14, static_cast<int>(state.range(1)), vob::ViewOptions{512, 512});
  // As the orderer projects its exterior faces for this view (xmpvo.cpp), with the front
  // sheet's inner edges left out as on this conforming surface.
  vob::xmpvo::Signs signs;
  signs.g = vob::xmpvo::ViewGeometry::of(view);
  vob::xmpvo::Projection proj;
  const vob::Aabb box = scene.mesh().bounds();
  proj.run(ext, view, signs, box.center(), box.radius());
  vob::xmpvo::Arrangement arr;
  arr.lanes = loop.lanes;
  arr.lanes_avx512 = loop.avx512;
  arr.unswept_sheet = 1;
  arr.set_faces(ext);
  int64_t candidates = 0;
  for (auto _ : state) {
    candidates = arr.build(ext, proj, signs);
    benchmark::DoNotOptimize(arr.vertices.data());
  }
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["crossings"] = static_cast<double>(arr.vertices.size() - arr.projected_vertices);
  state.counters["per_candidate"] = benchmark::Counter(  // seconds a candidate pair
      static_cast<double>(candidates), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_XmpvoArrangement)->ArgsProduct({{0, 1, 2}, {0, 4}})->Unit(benchmark::kMillisecond);

}  // namespace
