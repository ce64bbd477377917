// The runner: prepares an orderer once per (algorithm, dataset), warms up, repeats the
// per-frame order R times per view, checks the last ordering with the oracle, and turns it
// all into one results record per (algorithm, dataset, view, size).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/orderer.h"
#include "harness/bench/registry.h"
#include "harness/bench/suite.h"
#include "harness/oracle/oracle.h"

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
  nlohmann::json phases_json() const;      // name -> {min, median}
  nlohmann::json total_json() const;       // {min, median}
  double total_median() const;
};
FrameMeasurement measure_frame(PreparedOrderer& p, const Camera& view, int warmup, int repeats);

// Throws std::logic_error when the ordering is not a permutation of the scene's primitives.
void check_complete(const Scene& scene, const Ordering& ordering, const std::string& who);

// The views of a dataset: its own cameras for hard cases about a view, else the Fibonacci
// set of `count` views (all, or only `indices`). Returns (view index, camera) pairs.
std::vector<std::pair<int, Camera>> dataset_views(const DatasetSpec& spec, const Scene& scene,
                                                  int count, const std::vector<int>& indices,
                                                  int width, int height, bool ortho, double zoom);

// Orderers of the registry that take this kind of scene, or the suite's list.
std::vector<std::string> algorithms_for(const std::vector<std::string>& listed, SceneKind kind);

struct RunOptions {
  std::string results_path;
  std::string image_dir;  // where image_views' PNGs go (empty: beside the results)
  std::function<void(const std::string&)> progress;  // one line per record
  std::function<bool()> stop_requested;  // asked between records: true ends the run early
  // Also search every cell dataset for interpenetrating cells (cell_overlap.h) before
  // measuring it; a dataset with such cells is an InputError naming the first pair.
  bool validate_full = false;
};
struct RunSummary {
  int written = 0;             // records this run appended
  int skipped = 0;             // keys already in the file
  int written_elsewhere = 0;   // computed here, but another process appended the key first
  int violations = 0;
  bool stopped = false;        // ended early on stop_requested
};
// Every record is appended to the results file as soon as it is finished (see
// harness/bench/results.h). An unwritable results file or image folder is reported
// (InputError) before any scene is made.
RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt);

// Facts of a scene independent of any orderer: n, and for cells b and the cell-type counts.
nlohmann::json scene_facts(const Scene& scene);
// Projected area of the exterior faces in pixels at the view (Cook et al.'s a): the
// number of (pixel centre, boundary face) pairs covered.
int64_t exterior_area_pixels(const Scene& scene, const Camera& view);

}  // namespace vob
