// The runner: expands a suite into jobs (jobs.h), skips those whose records are in the
// results file, measures the rest (measure.h) and hands each record to the reporters
// (reporters.h): images, results file, console.
#pragma once
#include <functional>
#include <string>

#include "harness/bench/job_plan.h"
#include "harness/bench/jobs.h"
#include "harness/bench/measure.h"
#include "harness/bench/progress.h"
#include "harness/bench/suite.h"
#include "harness/oracle/oracle.h"  // for the callers that judge orders themselves

namespace vob {

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
// (InputError) before any scene is made. Each job runs under its thread count (a TBB
// global_control; the suite's `threads` list), inside any limit the caller set.
RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt);

}  // namespace vob
