// The software HAVS frame (cpu sort + k-buffer, k = 2, analysis off) on the 200k-cell helix
// at 512x512, 4 views in turn, at 1 and 2 threads (tbb::global_control). items/s = cells;
// compare process CPU time and real time of two builds run in turn (same API before and after).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <vector>

#include "algorithms/havs/havs_frame.h"
#include "datasets/datasets.h"
#include "harness/view/view_set.h"

namespace {

struct HavsSetup {
  vob::Scene scene;
  vob::havs::FaceData fd;
  std::vector<vob::Camera> views;
};

const HavsSetup& havs_setup() {
  static const HavsSetup s = [] {
    HavsSetup h;
    vob::Params p("helix");
    p.set("cells", "200000");
    h.scene = vob::make_dataset("helix", p);
    h.fd = vob::havs::build_face_data(h.scene);
    vob::ViewOptions o;
    o.width = o.height = 512;
    for (int i = 0; i < 4; ++i) h.views.push_back(vob::fibonacci_view(h.scene.bounds(), 14, i, o));
    return h;
  }();
  return s;
}

// range(0): the thread limit.
void BM_HavsFrame(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(state.range(0)));
  const HavsSetup& s = havs_setup();
  vob::havs::SortBuffers sort;
  std::vector<int32_t> order;
  vob::Image image;
  size_t v = 0;
  int64_t fragments = 0;
  for (auto _ : state) {
    const vob::Camera& view = s.views[v++ % s.views.size()];
    vob::havs::sort_faces(s.fd, view, sort, order);
    fragments += vob::havs::render_kbuffer(s.fd, view, order, 2, image).fragments;
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(s.scene.mesh().num_cells()));
  state.counters["fragments"] = benchmark::Counter(double(fragments), benchmark::Counter::kAvgIterations);
}

BENCHMARK(BM_HavsFrame)
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
