// Probes: measurements that are not "orderer x dataset x view" (sort micro-benchmarks, GL
// race counts, layer-extraction shares, predicate stability counts). A probe lives in the
// plugin folder it measures and is registered in harness/bench/registry.cpp beside the
// orderers; its result becomes one ordinary record in the results file (docs/pipeline.md).
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct ProbeContext {
  const Scene* scene = nullptr;  // the dataset, when the probe entry lists datasets
  std::string dataset_label;
  std::vector<std::pair<int, Camera>> views;  // the suite's views of the scene (first size)
  int repeats = 3, warmup = 1;
  std::string image_dir;     // where the probe may write PNGs (absolute)
  std::string image_prefix;  // a file-safe stem unique to this job
  std::function<void(const std::string&)> progress;  // optional, one line per step
};

struct ProbeInfo {
  std::string name, summary;
  bool needs_scene = false;  // the suite entry must list datasets
  // Reads its parameters from `params` (keys it does not read are refused afterwards),
  // measures, and returns the record's "result" object; image paths it wrote go in
  // result["images"] as {name: path relative to ctx.image_dir's parent} (the runner moves
  // them to the record's "images"). With params.dry_run() (suite validation, before any
  // work; ctx is empty) it only reads and checks its parameters and returns {}.
  std::function<nlohmann::json(Params& params, const ProbeContext& ctx)> run;
};

const std::vector<ProbeInfo>& probe_registry();
const ProbeInfo& find_probe(const std::string& name);  // InputError if unknown

}  // namespace vob
