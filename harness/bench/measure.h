// Measuring one job into a Record: an orderer prepared once per (spec, scene), warmed up,
// timed R times per view, its last ordering checked by the oracle; or one probe unit.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/jobs.h"
#include "harness/bench/orderer.h"
#include "harness/bench/ordering_check.h"
#include "harness/bench/probe.h"
#include "harness/bench/record.h"
#include "harness/bench/registry.h"
#include "harness/bench/verdict.h"

namespace vob {

struct PreparedOrderer {
  std::string spec;                  // as given: "havs:k=6"
  std::unique_ptr<Orderer> orderer;
  const OrdererInfo* info = nullptr;  // the registration: name, scene kind, parameters
  Scene scene;                       // fresh copy: the orderer pays for what it derives
  PhaseClock prepare_clock;
  double prepare_seconds = 0;
};
// InputError when the orderer does not take this kind of scene.
PreparedOrderer prepare_orderer(const std::string& spec, const Scene& scene);

struct FrameMeasurement {
  Ordering ordering;                       // of the last repeat
  std::vector<std::vector<std::pair<std::string, double>>> repeats;  // phases per repeat
  nlohmann::json phases_json() const;      // name -> {min, median, samples}
  nlohmann::json total_json() const;       // {min, median, samples}: seconds, repeat order
  double total_median() const;
};
FrameMeasurement measure_frame(PreparedOrderer& p, const Camera& view, int warmup, int repeats);

struct Measurement {
  Record record;
  Ordering ordering;
  std::optional<Verdict> verdict;  // when the suite has the oracle on
  // Compositing orderers whose images the suite may want: what it composited and its exact
  // composite (shown_images), made while the orderer still holds this view.
  std::optional<ShownImages> composited;
  bool violated = false;  // the verdict has violations (not an input fault)
};
// `base` holds what every record of the dataset shares (suite, dataset, row, dataset_spec,
// facts, threads, tags, context).
Measurement measure_orderer_job(const Job& job, PreparedOrderer& p, const Scene& scene,
                                const SuiteSpec& suite, const Record& base);
// The rest of measure_orderer_job once the frames are measured (by measure_frame, or in
// turns with other orderers): the record, and the verdict when the suite has the oracle on.
Measurement finish_orderer_job(const Job& job, PreparedOrderer& p, const Scene& scene, const SuiteSpec& suite,
                               const Record& base, FrameMeasurement m);

// Runs one probe unit (scene null for a sceneless probe); the record's result is what the
// probe returned, its images moved to the record.
Record run_probe_job(const Job& job, const Scene* scene, const SuiteSpec& suite, const DatasetSpec* ds,
                     const Record& base, const std::string& image_dir,
                     const std::function<void(const std::string&)>& progress);

// Facts of a scene independent of any orderer: n, and for cells b and the cell-type counts.
nlohmann::json scene_facts(const Scene& scene);
// Projected area of the exterior faces in pixels at the view (Cook et al.'s a): the
// number of (pixel centre, boundary face) pairs covered.
int64_t exterior_area_pixels(const Scene& scene, const Camera& view);

}  // namespace vob
