#include "harness/cli/dry_run.h"

#include <cstdio>

#include "harness/bench/progress.h"

namespace vob {

namespace {
std::string units(double cost) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", cost);
  return buf;
}

// " ~0.12 s" or " ~03:10" when calibrated, else "".
std::string time_of(double cost, const KnownRecords& known) {
  const double s = cost * known.seconds_per_unit();
  if (!(s > 0)) return "";
  if (s >= 60) return " ~" + ProgressTracker::clock_text(s);
  char buf[32];
  std::snprintf(buf, sizeof buf, " ~%.2g s", s);
  return buf;
}
}  // namespace

DryRunTotals& DryRunTotals::operator+=(const DryRunTotals& o) {
  jobs += o.jobs;
  to_do += o.to_do;
  cost += o.cost;
  return *this;
}

DryRunTotals print_dry_run(std::ostream& out, const SuiteSpec& suite, const RunTags& tags,
                           const KnownRecords& known) {
  const RunPlan plan = plan_run(suite, tags, known);
  out << "suite " << tags.suite_name(suite) << ": " << plan.jobs() << " jobs\n";
  for (const PlannedDataset& d : plan.datasets) {
    if (d.label.empty())
      out << "  probes without a scene";
    else
      out << "  dataset " << d.label << ": ~" << units(d.primitives) << " " << scene_kind_name(d.kind)
          << " (size from " << d.size_from << (d.views_note.empty() ? "" : "; " + d.views_note) << ")";
    out << ", " << d.jobs.size() << " jobs, " << d.jobs.size() - d.to_do() << " done, cost "
        << units(d.cost_to_do()) << time_of(d.cost_to_do(), known) << "\n";
    for (const PlannedJob& j : d.jobs)
      out << "    " << j.key << "  cost " << units(j.cost) << time_of(j.cost, known)
          << (j.done ? "  [done: skipped]" : "") << "\n";
  }
  return {plan.jobs(), plan.to_do(), plan.cost_to_do()};
}

void print_dry_run_total(std::ostream& out, const std::string& name, const DryRunTotals& t,
                         const KnownRecords& known, const std::string& results_path,
                         const KnownRecords* costs, const std::string& costs_path) {
  const KnownRecords& rate = costs ? *costs : known;
  const std::string rate_file = costs ? costs_path : "the results file";
  out << name << ": " << t.jobs << " jobs (" << t.jobs - t.to_do << " already done in " << results_path
      << "), " << t.to_do << " to compute, cost " << units(t.cost) << " units";
  if (rate.seconds_per_unit() > 0)
    out << ", ~" << ProgressTracker::clock_text(t.cost * rate.seconds_per_unit()) << " (calibrated from the frame times of "
        << rate.timed << " records in " << rate_file << "; oracle, images and scenes are not in them, so a lower bound)\n";
  else
    out << " (uncalibrated: no records in " << rate_file << " to turn units into seconds)\n";
}

}  // namespace vob
