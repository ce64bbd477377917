// SXMPVO's tiny-face entry kernels side by side in one run (issue 16): the scalar loop and
// AVX2's four lanes along a row, each writing the entries of every tiny triangle of the 1M-cell helix's exterior at one view of
// 14 at 512x512 (the faces phase III gives the tiny path), one thread. A kernel this CPU
// cannot run is skipped. range(0): the kernel (see kKernels), range(1): the view. Counters:
// the faces, their entries, and the time per face.
#include <benchmark/benchmark.h>

#include <vector>

#include "algorithms/sxmpvo/tiny_faces.h"
#include "datasets/datasets.h"
#include "harness/geometry/predicates.h"
#include "harness/view/view_set.h"

namespace {

struct Kernel {
  const char* name;
  vob::sxmpvo::TinyEntriesFn (*get)();
};
const Kernel kKernels[] = {{"scalar", &vob::sxmpvo::tiny_entries_baseline},
                           {"avx2", &vob::sxmpvo::tiny_entries_avx2}};

struct TinyFace {
  vob::Vec3 v[3];
  int sign;
  vob::SampleRect box;
};

const vob::Scene& helix_1m() {
  static const vob::Scene scene = [] {
    vob::Params p("helix");
    p.set("cells", "1000000");
    return vob::make_dataset("helix", p);
  }();
  return scene;
}

// The exterior triangles phase III sends to the tiny path at this view, with their phase-I
// signs (orient3d of the face's points and the eye, as MpvoCore computes them).
std::vector<TinyFace> tiny_faces(const vob::SampleFrame& frame) {
  const vob::ExteriorFaces& ext = helix_1m().exterior_faces();
  std::vector<vob::ProjectedVertex> projected(ext.points.size());
  for (size_t k = 0; k < ext.points.size(); ++k) projected[k] = vob::ProjectedVertex::of(frame, ext.points[k]);
  std::vector<TinyFace> out;
  for (size_t i = 0; i < ext.face.size(); ++i) {
    if (ext.size[i] != 3) continue;
    TinyFace f;
    if (vob::sxmpvo::sample_box(frame, projected.data(), &ext.vertex[4 * i], 3, f.box) !=
        vob::sxmpvo::BoxKind::Tiny)
      continue;
    for (int k = 0; k < 3; ++k) f.v[k] = ext.corners[4 * i + k];
    f.sign = frame.ortho() ? -vob::orient_direction(f.v[0], f.v[1], f.v[2], frame.forward())
                           : vob::orient3d(f.v[0], f.v[1], f.v[2], frame.eye());
    if (f.sign != 0) out.push_back(f);
  }
  return out;
}

void BM_TinyEntries(benchmark::State& state) {
  const Kernel& kernel = kKernels[state.range(0)];
  const vob::sxmpvo::TinyEntriesFn fn = kernel.get();
  state.SetLabel(kernel.name);
  if (!fn) {
    state.SkipWithError("this CPU cannot run the kernel");
    return;
  }
  const vob::Scene& scene = helix_1m();
  const vob::Camera view =
      vob::fibonacci_view(scene.bounds(), 14, static_cast<int>(state.range(1)), vob::ViewOptions{512, 512});
  const vob::SampleFrame frame(view, 1);
  const std::vector<TinyFace> faces = tiny_faces(frame);
  std::vector<vob::sxmpvo::ABuffer::Raw> entries(faces.size() * 4 + vob::sxmpvo::kTinyEntrySlots);
  size_t used = 0;
  for (auto _ : state) {
    used = 0;
    for (size_t i = 0; i < faces.size(); ++i) {
      if (entries.size() < used + vob::sxmpvo::kTinyEntrySlots) entries.resize(2 * entries.size());
      used += fn(frame, faces[i].v, faces[i].sign, faces[i].box, static_cast<int32_t>(i), static_cast<int32_t>(i),
                 entries.data() + used);
    }
    benchmark::DoNotOptimize(entries.data());
  }
  state.counters["faces"] = static_cast<double>(faces.size());
  state.counters["entries"] = static_cast<double>(used);
  state.counters["per_face"] = benchmark::Counter(  // seconds a face
      static_cast<double>(faces.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TinyEntries)->ArgsProduct({{0, 1}, {0, 4}})->Unit(benchmark::kMillisecond);

}  // namespace
