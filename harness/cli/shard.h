// `--shard I/N`, `--costs FILE`, `--ranks R`, `--mpi` and `--pin` of run and reproduce
// (docs/pipeline.md "Shards, merge and the MPI farm"): the job groups of the suites
// (job_partition.h), shard I's part of them, and the farm module loaded on --mpi.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/bench/farm.h"
#include "harness/bench/job_partition.h"

namespace vob {

struct SpreadOptions {
  std::string shard;   // "I/N"
  std::string costs;   // results file whose recorded times weigh the groups
  int ranks = 0;       // --dry-run: the makespan on this many ranks
  bool mpi = false, pin = false;
  int index = 0, count = 0;  // the parsed shard (count 0: none)

  void add_to(CLI::App& cmd);
  // Checks the combination (InputError): --shard's form, --pin only with --mpi, --ranks only
  // with --dry-run, --mpi not with --shard.
  void check(bool dry_run);
  bool sharded() const { return count > 0; }
  std::string shard_text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// Shard I/N's groups: planned from --costs alone (never from the shard's own results file),
// so that every shard computes the same partition. Prints one line about the shard to `log`.
// Returns the filter for RunOptions::take_group.
std::function<bool(const std::string&)> shard_filter(const std::vector<FarmSuite>& suites,
                                                     const SpreadOptions& spread, std::ostream& log);

// `--dry-run --ranks R`: the estimated makespan on R ranks and what bounds it.
void print_makespan(std::ostream& out, const std::vector<JobGroup>& groups, int ranks,
                    const RecordedTimes& times, const std::string& times_from);

// Loads libvobench-mpi.so and runs the farm (InputError when this build has no MPI).
int run_farm(const FarmRequest& request);

}  // namespace vob
