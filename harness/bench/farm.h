// The MPI task farm's request (docs/pipeline.md "Shards, merge and the MPI farm"): what
// `vobench run SUITE --mpi` and `vobench reproduce NAME --mpi` hand to the farm, which lives
// in its own module, libvobench-mpi.so (harness/mpi/), beside libvobench.so and loaded
// only on --mpi, so that neither the program nor libvobench.so needs MPI to run.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "harness/bench/job_partition.h"
#include "harness/bench/jobs.h"
#include "harness/bench/suite.h"

namespace vob {

struct FarmSuite {
  SuiteSpec suite;
  RunTags tags;
};

struct FarmRequest {
  std::string name;                 // for messages: "run quick", "reproduce cook-table4"
  std::vector<FarmSuite> suites;
  std::string results_path;         // rank 0 appends every record here
  std::string costs_path;           // recorded times to order the groups by (empty: results_path)
  bool validate_full = false;
  bool pin = false;                 // each rank on one core (sched_setaffinity)
  // Run by rank 0 only: before the farm (e.g. reproduce --force clearing the folder) and
  // after it with the farm's status (the tables); null: nothing.
  std::function<void()> before;
  std::function<int(int status)> after;
  std::function<int()> stop_signal;  // asked between messages: 0, or the signal that asks to stop
};

// The job groups of the suites (each with its tags), costed from `times`, done from `known`.
std::vector<JobGroup> plan_groups(const std::vector<FarmSuite>& suites, const KnownRecords& known,
                                  const RecordedTimes& times);

// The failed jobs of a farm go to RESULTS.failed.jsonl beside RESULTS.jsonl.
std::string failures_path(const std::string& results_path);
// libvobench-mpi.so beside the libvobench.so this code is in.
std::string farm_module_path();

}  // namespace vob

// The module's entry point: runs the farm on this rank (MPI_Init to MPI_Finalize) and
// returns the process's exit status (workers: 0 unless MPI failed).
extern "C" int vobench_mpi_farm(const vob::FarmRequest* request);
#define VOBENCH_MPI_FARM_ENTRY "vobench_mpi_farm"
