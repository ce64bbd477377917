// Expanding a suite into jobs (docs/pipeline.md "Jobs and keys"): (orderer spec x dataset x
// size x view) and (probe unit x dataset). Each job has the key that names its record in
// the results file; a job whose key is there already is skipped.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "harness/bench/suite.h"
#include "harness/view/camera.h"

namespace vob {

// Who runs the suite: `vobench run` (no reproduction) or `vobench reproduce`.
struct RunTags {
  std::string reproduction;  // empty: not run by reproduce
  std::string paper;         // empty: null (the generic report)
  std::string scale = "default";
  std::string suite_name(const SuiteSpec& s) const;  // "REPRO/SUITE" or "SUITE"
  std::string key_suffix() const;                    // "" or "|tiny", "|full"
};

// The TBB parallelism in effect now (the job's thread count once the runner set it).
int run_threads();
// The parallelism a job with thread count `threads` (a suite entry; 0: all cores) gets under
// the limits in effect now (e.g. `--threads`): what its key and record say.
int effective_threads(int threads);
// "|rRwW|tT": the timing settings of a probe key (orderer keys add oracle, ss, imgerr).
std::string settings_key(int repeats, int warmup, int threads);

struct Job {
  enum class Kind { Orderer, Probe } kind = Kind::Orderer;
  std::string key;
  std::string spec;               // orderer spec ("havs:k=6"); empty for a probe
  const ProbeSpec* probe = nullptr;
  int w = 0, h = 0, view_index = 0;
  int threads = 0;                // the suite's entry the job runs under (0: all cores)
  Camera camera;
};

// A scene the suite needs, and what runs on it. Suite datasets come first, in order; a
// probe's own datasets after them; the same dataset label is one plan (one scene).
struct DatasetPlan {
  DatasetSpec dataset;
  bool orderers = false;                  // the suite's algorithms run on it
  std::vector<const ProbeSpec*> probes;   // probe units on it
};
std::vector<DatasetPlan> plan_datasets(const SuiteSpec& suite);
// Probe units without a scene (run once each, after the datasets).
std::vector<const ProbeSpec*> sceneless_probes(const SuiteSpec& suite);

// The jobs of one plan on its scene: per orderer spec, per thread count, per size, per view;
// then the probes, per thread count. Thread counts with the same effective value run once.
std::vector<Job> dataset_jobs(const SuiteSpec& suite, const DatasetPlan& plan, const Scene& scene,
                              const RunTags& tags);
std::vector<Job> sceneless_jobs(const SuiteSpec& suite, const ProbeSpec& probe, const RunTags& tags);

// The suite's views of a dataset at w x h: its view_directions, the frames of its orbit
// (all, spread or listed indices), or the dataset's own cameras
// (hard cases about a view), or the Fibonacci view set (all, spread or listed indices);
// with `fit`, each window fitted to the bounding box at w*h pixels (view/fit.h).
std::vector<std::pair<int, Camera>> suite_views(const SuiteSpec& suite, const DatasetSpec& ds,
                                                const Scene& scene, int w, int h);

// The views of a dataset: its own cameras for hard cases about a view, else the Fibonacci
// set of `count` views (all, or only `indices`). Returns (view index, camera) pairs.
std::vector<std::pair<int, Camera>> dataset_views(const DatasetSpec& spec, const Scene& scene,
                                                  int count, const std::vector<int>& indices,
                                                  int width, int height, bool ortho, double zoom);

// Orderers of the registry that take this kind of scene, or the suite's list.
std::vector<std::string> algorithms_for(const std::vector<std::string>& listed, SceneKind kind);

}  // namespace vob
