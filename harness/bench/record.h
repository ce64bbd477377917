// One line of a results file (docs/pipeline.md "Records"): what measuring one job yields,
// as a struct; to_json is the one place that names the record's fields.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/view/camera.h"

namespace vob {

constexpr int kSchemaVersion = 2;  // docs/record.schema.json

struct Record {
  // Every record.
  std::string key, suite;
  std::string dataset, row;       // dataset label and table row; empty for a sceneless probe
  nlohmann::json dataset_spec;    // null for a sceneless probe
  nlohmann::json facts;           // scene_facts(): kind, n, points, b, cell_types | dims, voxels
  int repeats = 0, warmup = 0, threads = 0;
  bool interleaved = false;       // its frames took turns with the dataset's other orderers
  std::string reproduction, paper, scale;  // when run by reproduce (paper empty: null)
  std::string run_id;             // names the run's context line (context.h)
  // Where it ran (runner.h RunOptions::placement): host, rank, ranks, ranks_on_host, and
  // core (--pin) or shard ("I/N") when set; its keys go to the top level of the record.
  nlohmann::json placement;
  double job_seconds = 0;         // wall time of the job (frames, oracle, images; or the probe)

  // Orderer records.
  std::string algorithm;          // the spec as the suite gave it
  std::string orderer;            // registry name
  nlohmann::json parameters, claims;
  std::string raster = "exact";   // the oracle's sampling rule (harness/raster/raster_rule.h)
  int w = 0, h = 0, view_index = 0, views = 0;
  // The view indices the suite asks of this data set (all of 0..views-1, or its view_indices
  // or spread_views): a report knows a view lost by every orderer of a run from these.
  std::vector<int> views_asked;
  Camera camera;
  nlohmann::json phases, total, prepare, bytes, cycles, counters;
  std::optional<int64_t> a;       // exterior area in pixels (cells, exterior_area)
  nlohmann::json oracle, input_fault, image_error, images;  // null: absent
  nlohmann::json oracle_cell_order;  // compositing orderers: the derived cell order's count

  // Probe records (probe non-empty; parameters above are the probe's).
  std::string probe;
  double seconds = 0;
  nlohmann::json result;

  nlohmann::json to_json() const;
};

}  // namespace vob
