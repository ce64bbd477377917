// Spreading a run over shards and ranks (docs/pipeline.md "Shards, merge and the MPI farm"):
// the jobs of a plan grouped by (dataset, orderer spec or probe), the unit that is prepared
// once and so never split; each group's cost from the job_plan.h model, or from the times a
// previous results file recorded; a deterministic partition into N shards and the list
// schedule (largest group first, to the least loaded rank) that estimates a farm's makespan.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "harness/bench/job_plan.h"

namespace vob {

// What a results file says about the time jobs take: each record's own seconds, each
// orderer's prepare per dataset, and a rate (seconds per cost unit) for jobs it lacks.
struct RecordedTimes {
  std::map<std::string, double> job_seconds;      // key -> seconds (job_seconds, else frames)
  std::map<std::string, double> prepare_seconds;  // "DATASET|SPEC" -> prepare seconds
  double seconds = 0, units = 0;                  // the rate's sums
  size_t records = 0;                             // records that gave a time
  // Nothing when path is empty or names no file.
  static RecordedTimes read(const std::string& path);
  double seconds_per_unit() const { return units > 0 ? seconds / units : 0; }
};

struct JobGroup {
  std::string id;                 // "SUITE / DATASET / UNIT": the same in every shard and rank
  size_t suite = 0;               // which of the plans it came from
  std::string dataset, unit;      // dataset label ("" for probes without a scene), spec or probe
  std::vector<std::string> keys, done;  // its jobs' keys; those already in the results file
  double cost = 0, cost_to_do = 0;      // seconds when calibrated, else cost units
};

std::string group_id(const std::string& suite, const std::string& dataset, const std::string& unit);

// Appends the groups of one suite's plan (in plan order); `suite_name` as RunTags names it.
// Costs are seconds when `times` has a rate (recorded jobs at their recorded time, prepare
// once per group), else cost units.
void add_groups(std::vector<JobGroup>& out, size_t suite_index, const std::string& suite_name,
                const RunPlan& plan, const RecordedTimes& times);

// List scheduling, largest first: items sorted by cost (descending; ties by index), each
// given to the part with the least load so far (ties: the lowest part). Deterministic.
struct Schedule {
  std::vector<int> part;       // per item
  std::vector<double> loads;   // per part
  double makespan = 0, total = 0;
  int largest = -1;            // the costliest item: no schedule ends before it does
};
Schedule list_schedule(const std::vector<double>& costs, int parts);

// The groups of shard `index` (1-based) of `count`, balanced by each group's whole cost (done
// jobs included, so every shard computes the same partition whatever its own file holds).
std::vector<const JobGroup*> shard_groups(const std::vector<JobGroup>& groups, int index, int count);

}  // namespace vob
