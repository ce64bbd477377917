// The two roles of the farm (harness/mpi): rank 0 coordinates, every other rank works.
#pragma once
#include <nlohmann/json.hpp>

#include "harness/bench/farm.h"

namespace vob::farm {

// Rank 0: hands out the groups still to do, largest first, as workers become free; appends
// every record and context line it receives to the results file, failures to
// RESULTS.failed.jsonl. Returns the exit status (2 when a job failed, 128 + signal when
// stopped), after req.after.
int coordinate(const FarmRequest& req, int ranks, const nlohmann::json& placement);
// A worker: measures the groups it is given and sends their records to rank 0.
void work(const FarmRequest& req, const nlohmann::json& placement);

}  // namespace vob::farm
