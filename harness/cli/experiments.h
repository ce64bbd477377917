// Reproducible experiments: `vobench reproduce NAME` runs one and writes NAME.md (its table,
// beside the paper's numbers where the paper has them) and NAME.json (the same rows) under
// its output folder, plus a report with figures.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace vob {

struct ExperimentContext {
  std::string out_dir;
  bool force = false;   // start afresh: drop the records and images already in out_dir
  bool full = false;    // the paper's full sizes where they are opt-in
};

struct Experiment {
  std::string name, summary;
  std::function<int(const ExperimentContext&)> run;
};

const std::vector<Experiment>& experiment_registry();

// Runs reports/report.py on results files into out_dir; `name` adds NAME.md / NAME.json.
// Returns the script's exit status.
int run_report(const std::vector<std::string>& results, const std::string& out_dir,
               const std::string& title, const std::string& name,
               const std::vector<std::string>& include_md = {});

// Runs the suite files (relative to datasets/suites/) into out_dir/results.jsonl, keeping
// the records already there unless ctx.force, printing progress; then the report. Returns
// the report's status, or 130 / 143 when SIGINT / SIGTERM stopped the run (no report then).
int run_suite_experiment(const std::vector<std::string>& suite_files, const std::string& name,
                         const std::string& title, const ExperimentContext& ctx);

}  // namespace vob
