// The exact rule's rasterizer (PolygonRaster::scan, its row kernel the widest this CPU
// runs) over the exterior faces that SXMPVO's phase III rasterizes whole: those too large
// for its tiny path, at one view of 14 at 512x512, one thread (issue 16). range(0): the
// scene (0: the 187,395-cell helix of cook-table4's bluntfin row, 1: zoo), range(1): the
// view. Counters: the faces, their covered samples, and the time per sample.
#include <benchmark/benchmark.h>

#include <vector>

#include "algorithms/sxmpvo/tiny_faces.h"
#include "datasets/datasets.h"
#include "harness/raster/polygon_raster.h"
#include "harness/view/view_set.h"

namespace {

const vob::Scene& scene_of(int which) {
  static const vob::Scene helix = [] {
    vob::Params p("helix");
    p.set("cells", "187395");
    p.set("faces", "13516");
    return vob::make_dataset("helix", p);
  }();
  static const vob::Scene zoo = vob::make_dataset("zoo", vob::Params("zoo"));
  return which == 0 ? helix : zoo;
}

struct LargeFace {
  vob::Vec3 v[4];
  int n;
};

// The faces sample_box does not call tiny (phase III sends them to PolygonRaster).
std::vector<LargeFace> large_faces(const vob::Scene& scene, const vob::SampleFrame& frame) {
  const vob::ExteriorFaces& ext = scene.exterior_faces();
  std::vector<vob::ProjectedVertex> projected(ext.points.size());
  for (size_t k = 0; k < ext.points.size(); ++k) projected[k] = vob::ProjectedVertex::of(frame, ext.points[k]);
  std::vector<LargeFace> out;
  for (size_t i = 0; i < ext.face.size(); ++i) {
    vob::SampleRect box;
    const vob::sxmpvo::BoxKind kind = vob::sxmpvo::sample_box(frame, projected.data(), &ext.vertex[4 * i], ext.size[i], box);
    if (kind == vob::sxmpvo::BoxKind::None || (kind == vob::sxmpvo::BoxKind::Tiny && ext.size[i] == 3)) continue;
    LargeFace f;
    f.n = ext.size[i];
    for (int k = 0; k < f.n; ++k) f.v[k] = ext.corners[4 * i + k];
    out.push_back(f);
  }
  return out;
}

void BM_LargeFaceScan(benchmark::State& state) {
  const vob::Scene& scene = scene_of(static_cast<int>(state.range(0)));
  const vob::Camera view =
      vob::fibonacci_view(scene.bounds(), 14, static_cast<int>(state.range(1)), vob::ViewOptions{512, 512});
  const vob::SampleFrame frame(view, 1);
  const std::vector<LargeFace> faces = large_faces(scene, frame);
  vob::PolygonRaster raster;
  int64_t samples = 0;
  double sum = 0;
  for (auto _ : state) {
    samples = 0;
    for (const LargeFace& f : faces) {
      if (!raster.setup(frame, f.v, f.n)) continue;
      raster.scan(frame.bounds(), [&](const vob::RowHits& hits, int m) {
        samples += m;
        sum += hits.t[m - 1];
      });
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetLabel(state.range(0) == 0 ? "helix 187k" : "zoo");
  state.counters["faces"] = static_cast<double>(faces.size());
  state.counters["samples"] = static_cast<double>(samples);
  state.counters["per_sample"] = benchmark::Counter(  // seconds a covered sample
      static_cast<double>(samples), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_LargeFaceScan)->ArgsProduct({{0, 1}, {0, 4}})->Unit(benchmark::kMillisecond);

}  // namespace
