#include "harness/bench/jobs.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <tbb/global_control.h>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/view/fit.h"
#include "harness/view/view_set.h"

namespace vob {
namespace {
std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// A view from a fixed direction, framed as the view set frames its views.
Camera direction_view(const Aabb& box, const ViewDirection& d, int w, int h, bool ortho, double zoom) {
  ViewOptions vo;
  vo.width = w;
  vo.height = h;
  vo.ortho = ortho;
  vo.zoom = zoom;
  Camera cam = fibonacci_view(box, 1, 0, vo);
  const double len = std::sqrt(d.from.x * d.from.x + d.from.y * d.from.y + d.from.z * d.from.z);
  cam.eye = box.center() + d.from * (box.radius() * kViewDistance / zoom / len);
  cam.target = box.center();
  cam.up = d.up;
  return cam;
}
}  // namespace

std::string RunTags::suite_name(const SuiteSpec& s) const {
  return reproduction.empty() ? s.name : reproduction + "/" + s.name;
}

int run_threads() {
  return static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

int effective_threads(int threads) {
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  return run_threads();
}

namespace {
// The suite's thread counts as (entry, effective count), the first of equal effective counts.
std::vector<std::pair<int, int>> thread_counts(const SuiteSpec& suite) {
  std::vector<std::pair<int, int>> out;
  for (int t : suite.threads) {
    const int e = effective_threads(t);
    if (std::none_of(out.begin(), out.end(), [&](const auto& p) { return p.second == e; })) out.emplace_back(t, e);
  }
  return out;
}
}  // namespace

std::string settings_key(int repeats, int warmup, int threads) {
  return "|r" + std::to_string(repeats) + "w" + std::to_string(warmup) + "|t" + std::to_string(threads);
}

std::string RunTags::key_suffix() const { return scale == "default" ? "" : "|" + scale; }

std::vector<DatasetPlan> plan_datasets(const SuiteSpec& suite) {
  std::vector<DatasetPlan> plans;
  const auto plan_of = [&](const DatasetSpec& ds) -> DatasetPlan& {
    for (auto& p : plans)
      if (p.dataset.label() == ds.label()) return p;
    plans.push_back({ds, false, {}});
    return plans.back();
  };
  for (const auto& ds : suite.datasets)
    if (!suite.algorithms.empty()) plan_of(ds).orderers = true;
  for (const auto& probe : suite.probes)
    for (const auto& ds : probe.datasets) plan_of(ds).probes.push_back(&probe);
  return plans;
}

std::vector<const ProbeSpec*> sceneless_probes(const SuiteSpec& suite) {
  std::vector<const ProbeSpec*> out;
  for (const auto& p : suite.probes)
    if (p.datasets.empty()) out.push_back(&p);
  return out;
}

namespace {
std::vector<std::pair<int, Camera>> unfitted_views(const SuiteSpec& suite, const DatasetSpec& ds,
                                                   const Scene& scene, int w, int h) {
  if (suite.orbit) {
    ViewOptions vo;
    vo.width = w;
    vo.height = h;
    vo.ortho = suite.ortho;
    vo.zoom = suite.zoom;
    std::vector<std::pair<int, Camera>> out;
    for (int i = 0; i < suite.views; ++i)
      if (suite.view_indices.empty() || std::count(suite.view_indices.begin(), suite.view_indices.end(), i))
        out.emplace_back(i, orbit_view(scene.bounds(), suite.views, i, vo));
    return out;
  }
  if (suite.view_directions.empty())
    return dataset_views(ds, scene, suite.views, suite.view_indices, w, h, suite.ortho, suite.zoom);
  std::vector<std::pair<int, Camera>> out;
  for (size_t i = 0; i < suite.view_directions.size(); ++i)
    out.emplace_back(int(i), direction_view(scene.bounds(), suite.view_directions[i], w, h, suite.ortho, suite.zoom));
  return out;
}
}  // namespace

std::vector<std::pair<int, Camera>> suite_views(const SuiteSpec& suite, const DatasetSpec& ds,
                                                const Scene& scene, int w, int h) {
  auto views = unfitted_views(suite, ds, scene, w, h);
  if (suite.fit)
    for (auto& [i, cam] : views) cam = fit_window_to_box(cam, scene.bounds(), int64_t(w) * h);
  return views;
}

std::vector<Job> dataset_jobs(const SuiteSpec& suite, const DatasetPlan& plan, const Scene& scene,
                              const RunTags& tags) {
  std::vector<Job> jobs;
  const std::string scope = tags.suite_name(suite), label = plan.dataset.label();
  const std::string view_set = suite.orbit ? "|o" : suite.view_directions.empty() ? "|v" : "|d";
  // Every setting that changes an orderer record (docs/pipeline.md "Jobs and keys").
  const std::string settings = "|r" + std::to_string(suite.repeats) + "w" + std::to_string(suite.warmup) +
                               (suite.oracle ? "|oracle" : "|nooracle") + "|ss" +
                               std::to_string(suite.supersample) + (suite.image_error ? "|imgerr" : "") +
                               (suite.raster == RasterRule::gl ? "|rgl" : "") + (suite.interleave ? "|interleaved" : "");
  const auto counts = thread_counts(suite);
  // Per spec, its thread counts one after the other: their times are side by side in time too.
  if (plan.orderers)
    for (const auto& spec : algorithms_for(suite.algorithms, scene.kind()))
      for (const auto& [t, effective] : counts)
        for (const auto& [w, h] : suite.sizes)
          for (const auto& [vi, cam] : suite_views(suite, plan.dataset, scene, w, h)) {
            Job j;
            j.spec = spec;
            j.threads = t;
            // A fitted window has the camera's size; the key keeps the suite's W x H.
            j.w = cam.width, j.h = cam.height, j.view_index = vi, j.camera = cam;
            j.key = scope + "|" + spec + "|" + label + view_set + std::to_string(vi) + "/" +
                    std::to_string(suite.views) + "|" + size_text(w, h) + settings + "|t" +
                    std::to_string(effective) + (suite.ortho ? "|ortho" : "") +
                    (suite.zoom != 1.0 ? "|zoom" + std::to_string(suite.zoom) : "") + (suite.fit ? "|fit" : "") +
                    tags.key_suffix();
            jobs.push_back(std::move(j));
          }
  for (const ProbeSpec* p : plan.probes)
    for (const auto& [t, effective] : counts) {
      Job j;
      j.kind = Job::Kind::Probe;
      j.probe = p;
      j.threads = t;
      j.key = scope + "|" + p->label() + "|" + label + settings_key(p->repeats, p->warmup, effective) +
              tags.key_suffix();
      jobs.push_back(std::move(j));
    }
  return jobs;
}

std::vector<Job> sceneless_jobs(const SuiteSpec& suite, const ProbeSpec& probe, const RunTags& tags) {
  std::vector<Job> jobs;
  for (const auto& [t, effective] : thread_counts(suite)) {
    Job j;
    j.kind = Job::Kind::Probe;
    j.probe = &probe;
    j.threads = t;
    j.key = tags.suite_name(suite) + "|" + probe.label() + "|" + settings_key(probe.repeats, probe.warmup, effective) +
            tags.key_suffix();
    jobs.push_back(std::move(j));
  }
  return jobs;
}

std::vector<std::pair<int, Camera>> dataset_views(const DatasetSpec& spec, const Scene& scene,
                                                  int count, const std::vector<int>& indices,
                                                  int width, int height, bool ortho, double zoom) {
  std::vector<std::pair<int, Camera>> out;
  if (spec.input.empty()) {
    const DatasetInfo& info = find_dataset(spec.name);
    if (info.views) {
      const auto cams = info.views(scene, width, height);
      for (size_t i = 0; i < cams.size(); ++i)
        if (indices.empty() || std::count(indices.begin(), indices.end(), int(i)))
          out.emplace_back(int(i), cams[i]);
      return out;
    }
  }
  ViewOptions vo;
  vo.width = width;
  vo.height = height;
  vo.ortho = ortho;
  vo.zoom = zoom;
  const Aabb box = scene.bounds();
  if (indices.empty())
    for (int i = 0; i < count; ++i) out.emplace_back(i, fibonacci_view(box, count, i, vo));
  else
    for (int i : indices) out.emplace_back(i, fibonacci_view(box, count, i, vo));
  return out;
}

std::vector<std::string> algorithms_for(const std::vector<std::string>& listed, SceneKind kind) {
  std::vector<std::string> out;
  for (const auto& a : listed) {
    if (a == "all") {
      for (const auto& info : orderer_registry())
        if (info.kind == kind && std::find(out.begin(), out.end(), info.name) == out.end())
          out.push_back(info.name);
      continue;
    }
    const auto name = Params::parse_spec(a).first;
    if (find_orderer(name).kind == kind && std::find(out.begin(), out.end(), a) == out.end())
      out.push_back(a);
  }
  return out;
}

}  // namespace vob
