#include "harness/bench/record.h"

namespace vob {

nlohmann::json Record::to_json() const {
  nlohmann::json j;
  j["key"] = key;
  j["schema_version"] = kSchemaVersion;
  j["run_id"] = run_id;
  j["suite"] = suite;
  j["parameters"] = parameters;
  j["repeats"] = repeats;
  j["warmup"] = warmup;
  if (interleaved) j["interleaved"] = true;
  j["threads"] = threads;
  if (placement.is_object())
    for (const auto& [k, v] : placement.items()) j[k] = v;
  j["job_seconds"] = job_seconds;
  if (!dataset_spec.is_null() || probe.empty()) {
    j["dataset"] = dataset;
    j["dataset_spec"] = dataset_spec;
    j["row"] = row;
  }
  if (facts.is_object())
    for (const auto& [k, v] : facts.items()) j[k] = v;
  if (!images.is_null()) j["images"] = images;
  if (!probe.empty()) {
    j["probe"] = probe;
    j["seconds"] = seconds;
    j["result"] = result;
  } else {
    j["algorithm"] = algorithm;
    j["orderer"] = orderer;
    j["claims"] = claims;
    j["raster"] = raster;
    j["w"] = w;
    j["h"] = h;
    j["pixels"] = int64_t(w) * h;
    j["view_index"] = view_index;
    j["views"] = views;
    if (!views_asked.empty()) j["views_asked"] = views_asked;
    j["camera"] = camera.to_json();
    j["phases"] = phases;
    j["total"] = total;
    j["prepare"] = prepare;
    j["bytes"] = bytes;
    j["cycles"] = cycles;
    j["counters"] = counters;
    if (a) j["a"] = *a;
    if (!oracle.is_null()) j["oracle"] = oracle;
    if (!oracle_cell_order.is_null()) j["oracle_cell_order"] = oracle_cell_order;
    if (!input_fault.is_null()) j["input_fault"] = input_fault;
    if (!image_error.is_null()) j["image_error"] = image_error;
  }
  if (!reproduction.empty()) {
    j["reproduction"] = reproduction;
    j["paper"] = paper.empty() ? nlohmann::json(nullptr) : nlohmann::json(paper);
    j["scale"] = scale;
  }
  return j;
}

}  // namespace vob
