// SXMPVO's tiny-face entry kernels, and the A-buffer's list ordering, side by side in one run (issue 16): the scalar loop and
// AVX2's four lanes along a row, each writing the entries of every tiny triangle of the 1M-cell helix's exterior at one view of
// 14 at 512x512 (the faces phase III gives the tiny path), one thread. A kernel this CPU
// cannot run is skipped. range(0): the kernel (see kKernels), range(1): the view. Counters:
// the faces, their entries, and the time per face.
#include <benchmark/benchmark.h>

#include <algorithm>
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
                           {"avx2", &vob::sxmpvo::tiny_entries_avx2},
                           {"avx512", &vob::sxmpvo::tiny_entries_avx512}};

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
  vob::sxmpvo::ABuffer::RawBatch entries;
  entries.reserve_more(faces.size() * 4 + vob::sxmpvo::kTinyEntrySlots);
  size_t used = 0;
  for (auto _ : state) {
    entries.clear();
    for (size_t i = 0; i < faces.size(); ++i) {
      entries.reserve_more(vob::sxmpvo::kTinyEntrySlots);
      entries.size += static_cast<size_t>(fn(frame, faces[i].v, faces[i].sign, faces[i].box,
                                             entries.add_face(static_cast<int32_t>(i), static_cast<int32_t>(i)),
                                             entries.at(entries.size)));
    }
    used = entries.size;
    benchmark::DoNotOptimize(entries.t.data());
  }
  state.counters["faces"] = static_cast<double>(faces.size());
  state.counters["entries"] = static_cast<double>(used);
  state.counters["per_face"] = benchmark::Counter(  // seconds a face
      static_cast<double>(faces.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TinyEntries)->ArgsProduct({{0, 1, 2}, {0, 4}})->Unit(benchmark::kMillisecond);

// ABuffer::order over every PIX list of the tiny faces' entries (ranks: the faces by
// centroid distance, as phase II gives them), with the lanes (lists up to 16 entries
// sorted by rank in AVX2) or the scalar insertion sort alone. range(0): 0 scalar, 1 lanes;
// range(1): the view. gather() runs once; order() reads its lists and writes new ones.
void BM_ABufferOrder(benchmark::State& state) {
  const bool lanes = state.range(0) == 1;
  state.SetLabel(lanes ? "lanes" : "scalar");
  const vob::sxmpvo::TinyEntriesFn fn = vob::sxmpvo::tiny_entries();
  const vob::Scene& scene = helix_1m();
  const vob::Camera view =
      vob::fibonacci_view(scene.bounds(), 14, static_cast<int>(state.range(1)), vob::ViewOptions{512, 512});
  const vob::SampleFrame frame(view, 1);
  const std::vector<TinyFace> faces = tiny_faces(frame);
  std::vector<int32_t> by_distance(faces.size()), rank(faces.size());
  std::vector<double> distance(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    distance[i] = vob::length((faces[i].v[0] + faces[i].v[1] + faces[i].v[2]) * (1.0 / 3) - view.eye);
    by_distance[i] = static_cast<int32_t>(i);
  }
  std::stable_sort(by_distance.begin(), by_distance.end(),
                   [&](int32_t a, int32_t b) { return distance[a] < distance[b]; });
  for (size_t k = 0; k < faces.size(); ++k) rank[by_distance[k]] = static_cast<int32_t>(k);
  vob::sxmpvo::ABuffer::RawBatch entries;
  for (size_t i = 0; i < faces.size(); ++i) {
    entries.reserve_more(vob::sxmpvo::kTinyEntrySlots);
    entries.size += static_cast<size_t>(fn(frame, faces[i].v, faces[i].sign, faces[i].box,
                                           entries.add_face(static_cast<int32_t>(2 * i), rank[i]), entries.at(entries.size)));
  }
  const size_t used = entries.size;
  vob::sxmpvo::ABuffer abuf;
  abuf.set_lanes(lanes);
  abuf.reset(frame.num_samples());
  abuf.append(entries);
  abuf.gather();
  for (auto _ : state) {
    abuf.order(0, abuf.pixels());
    benchmark::DoNotOptimize(abuf.begin(0));
  }
  state.counters["entries"] = static_cast<double>(used);
  state.counters["per_entry"] = benchmark::Counter(  // seconds an entry
      static_cast<double>(used), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ABufferOrder)->ArgsProduct({{0, 1}, {0, 4}})->Unit(benchmark::kMillisecond);

}  // namespace
