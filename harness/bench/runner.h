// The runner: expands a suite into jobs (jobs.h), skips those whose records are in the
// results file, measures the rest (measure.h) and hands each record to the reporters
// (reporters.h): images, results file, console.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "harness/bench/job_plan.h"
#include "harness/bench/jobs.h"
#include "harness/bench/measure.h"
#include "harness/bench/progress.h"
#include "harness/bench/suite.h"
#include "harness/oracle/oracle.h"  // for the callers that judge orders themselves

namespace vob {

// Where a run's records go when not into its results file (the MPI farm's workers send
// them to rank 0, which writes them).
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual bool done(const std::string& key) = 0;
  virtual bool report(const Record& rec) = 0;  // whether it was written
};

// The last scene a run made, kept for the next run on the same dataset (a farm worker
// given several groups of one dataset makes its scene once).
struct SceneCache {
  std::string label;
  std::shared_ptr<const Scene> scene;
};

struct RunOptions {
  std::string results_path;
  std::string image_dir;  // where image_views' PNGs go (empty: beside the results)
  std::function<void(const std::string&)> progress;  // one line per record
  std::function<bool()> stop_requested;  // asked between records: true ends the run early
  // Also search every cell dataset for interpenetrating cells (cell_overlap.h) before
  // measuring it; a dataset with such cells is an InputError naming the first pair.
  bool validate_full = false;
  RunTags tags;  // set by reproduce: key prefix and the records' reproduction, paper, scale
  // The [k/N] of the record lines, when the caller counts several suites (reproduce) and
  // has added this suite's plan, made from `known`, to it; null: the run counts its own jobs.
  ProgressTracker* tracker = nullptr;
  const KnownRecords* known = nullptr;  // with tracker: what the caller's plan was made from
  // Part of the suite only (shards, farm workers): the job groups (job_partition.h) whose
  // id this accepts; a dataset without one is not made. Null: every job.
  std::function<bool(const std::string& group_id)> take_group;
  RecordSink* sink = nullptr;   // null: the results file
  // Set: a job that throws (or whose scene cannot be made) is reported here, with its
  // group and the reason, and the run goes on; null: the exception ends the run.
  std::function<void(const std::string& key, const std::string& group, const std::string& reason)> on_failure;
  std::string run_id;           // empty: a new one (context.h)
  nlohmann::json context;       // null: this process's run context
  // The records' placement fields (record.h); null: this host, rank 0 of 1, alone.
  nlohmann::json placement;
  SceneCache* scene_cache = nullptr;
  // Whether the run writes its suite's plan line (job_plan.h plan_line) into the results
  // file before its jobs when any of them is still to do; false when the caller wrote it
  // (reproduce writes every suite's plan first). Never with a sink.
  bool write_plan = true;
};
struct RunSummary {
  int written = 0;             // records this run appended
  int skipped = 0;             // keys already in the file
  int written_elsewhere = 0;   // computed here, but another process appended the key first
  int violations = 0;
  int failed = 0;              // jobs reported to on_failure
  bool stopped = false;        // ended early on stop_requested
};
// Every record is appended to the results file as soon as it is finished (see
// harness/bench/results.h). An unwritable results file or image folder is reported
// (InputError) before any scene is made. Each job runs under its thread count (a TBB
// global_control; the suite's `threads` list), inside any limit the caller set.
RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt);
// The placement of a run on its own: this host, rank 0 of 1, alone on it (as far as it knows).
nlohmann::json lone_placement();

}  // namespace vob
