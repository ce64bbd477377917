// `--dry-run` of run and reproduce (docs/pipeline.md "Progress and --dry-run"): the jobs,
// grouped per dataset, each with its key, its cost in units of job_plan.h's model and, when
// earlier records calibrate it, an estimate in seconds; jobs whose key is in the results
// file are marked done. Makes no scene and writes nothing.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "harness/bench/job_plan.h"

namespace vob {

struct DryRunTotals {
  size_t jobs = 0, to_do = 0;
  double cost = 0;
  DryRunTotals& operator+=(const DryRunTotals& o);
};

// Lists one suite's jobs (its results file already read into `known`); returns its totals.
DryRunTotals print_dry_run(std::ostream& out, const SuiteSpec& suite, const RunTags& tags,
                           const KnownRecords& known);
// "NAME: N jobs (D already done), T to compute, cost C units, ~HH:MM:SS (calibrated from ...)"
// `costs`: records of another file (--costs) that calibrate the estimate instead of `known`'s.
void print_dry_run_total(std::ostream& out, const std::string& name, const DryRunTotals& t,
                         const KnownRecords& known, const std::string& results_path,
                         const KnownRecords* costs = nullptr, const std::string& costs_path = "");

}  // namespace vob
