// vobench run: run a suite and append its records to a results file (JSONL). Each record
// is on disk as soon as it is finished; SIGINT or SIGTERM stop the run after the record in
// progress (exit 130 or 143), and running the same command again resumes it.
#include <filesystem>
#include <iostream>

#include "harness/bench/job_partition.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/resources.h"
#include "harness/bench/runner.h"
#include "harness/cli/dry_run.h"
#include "harness/cli/commands.h"
#include "harness/cli/python_script.h"
#include "harness/cli/shard.h"
#include "harness/scene/input_error.h"
#include "harness/cli/stop_signals.h"
#include "harness/cli/thread_option.h"
#include "harness/cli/raster_option.h"
#include "harness/cli/vtk_render_child.h"

namespace vob {

Command add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "run a suite (datasets/suites/*.json) into RESULTS.jsonl");
  auto suite = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("suite", *suite, "suite JSON")->required();
  cmd->add_option("-o,--output", *out,
                  "results file (JSONL); records already in it are skipped, new ones appended")
      ->required();
  auto validate = std::make_shared<std::string>("cells");
  cmd->add_option("--validate", *validate,
                  "cells: per-cell checks (default); full: also every pair of interpenetrating "
                  "cells of each cell dataset, before it is measured")
      ->check(CLI::IsMember({"cells", "full"}));
  auto format = std::make_shared<std::string>("jsonl");
  cmd->add_option("--format", *format,
                  "jsonl (default); gbench: also Google Benchmark's JSON of the file's records "
                  "beside it (RESULTS.gbench.json)")
      ->check(CLI::IsMember({"jsonl", "gbench"}));
  auto dry_run = std::make_shared<bool>(false);
  cmd->add_flag("--dry-run", *dry_run,
                "list the jobs (done ones marked) with their estimated cost and exit; makes no scene, "
                "writes nothing");
  auto threads = std::make_shared<ThreadOption>();
  threads->add_to(*cmd);
  auto spread = std::make_shared<SpreadOptions>();
  spread->add_to(*cmd);
  auto raster = std::make_shared<RasterOption>();
  raster->add_to(*cmd);
  return [=]() {
    spread->check(*dry_run);
    SuiteSpec s = SuiteSpec::load(*suite);
    threads->apply(s);
    raster->apply(s);
    const auto limit = threads->limit();
    std::error_code ec;
    if (std::filesystem::exists(*out, ec) && !std::filesystem::is_regular_file(*out, ec))
      throw InputError("--output", "'" + *out + "'", "exists and is not a results file");
    const std::vector<FarmSuite> suites{{s, RunTags{}}};
    if (*dry_run) {
      const KnownRecords known = KnownRecords::read(*out);
      const KnownRecords costs = spread->costs.empty() ? KnownRecords() : KnownRecords::read(spread->costs);
      print_dry_run_total(std::cout, "run " + s.name, print_dry_run(std::cout, s, RunTags{}, known), known, *out,
                          spread->costs.empty() ? nullptr : &costs, spread->costs);
      if (spread->sharded()) shard_filter(suites, *spread, std::cout);
      if (spread->ranks > 0) {
        const std::string from = spread->costs.empty() ? *out : spread->costs;
        const RecordedTimes times = RecordedTimes::read(from);
        print_makespan(std::cout, plan_groups(suites, known, times), spread->ranks, times, from);
      }
      return 0;
    }
    const StopSignals signals;
    if (spread->mpi) {
      FarmRequest req;
      req.name = "run " + s.name;
      req.suites = suites;
      req.results_path = *out;
      req.costs_path = spread->costs;
      req.validate_full = *validate == "full";
      req.pin = spread->pin;
      req.stop_signal = [] { return StopSignals::received(); };
      if (*format == "gbench")
        req.after = [out](int status) {
          return status == 0 ? run_python_script("gbench.py", {*out, "-o", gbench_path(*out)}) : status;
        };
      if (s.vtk_render)
        std::cerr << "vtk_render: not drawn by an MPI farm: vobench-vtk render --suite " << *suite << " afterwards\n";
      return run_farm(req);
    }
    RunOptions opt;
    if (spread->sharded()) {
      opt.take_group = shard_filter(suites, *spread, std::cerr);
      opt.placement = lone_placement();
      opt.placement["shard"] = spread->shard_text();
    }
    opt.results_path = *out;
    opt.validate_full = *validate == "full";
    opt.progress = [](const std::string& line) { std::cerr << line << std::endl; };
    opt.stop_requested = [] { return StopSignals::received() != 0; };
    {  // records kept from other builds: say whose numbers they are
      const std::string revision = source_revision();
      const KnownRecords known = KnownRecords::read(*out);
      PlannedJobFilter take;
      if (opt.take_group)
        take = [&](const PlannedDataset& d, const PlannedJob& j) {
          return opt.take_group(group_id(s.name, d.label, j.unit));
        };
      const std::string note =
          other_revisions_note(done_by_other_revisions(plan_run(s, RunTags{}, known), known, revision, take), revision,
                               "a new -o file");
      if (!note.empty()) std::cerr << "run " << s.name << ": " << note << "\n";
    }
    const RunSummary r = run_suite(s, opt);
    std::cerr << "run " << s.name << ": " << r.written << " records written, " << r.skipped
              << " already present, ";
    if (r.written_elsewhere) std::cerr << r.written_elsewhere << " written meanwhile by another run, ";
    std::cerr << r.violations << " with oracle violations -> " << *out << "\n";
    if (!r.stopped) {
      int vtk = 0;  // the suite's vtk_render entry: vobench-vtk, beside the results file
      if (s.vtk_render && spread->sharded())
        std::cerr << "vtk_render: not drawn by a shard: vobench-vtk render --suite " << *suite << " after the merge\n";
      else
        vtk = run_vtk_render(s, std::filesystem::path(*out).has_parent_path()
                                    ? std::filesystem::path(*out).parent_path().string() : ".");
      if (vtk != 0) return vtk;
      return *format == "gbench" ? run_python_script("gbench.py", {*out, "-o", gbench_path(*out)}) : 0;
    }
    const int sig = StopSignals::received();
    std::cerr << "run " << s.name << ": stopped by " << StopSignals::name(sig) << " with "
              << r.written << " records written; run the same command again to resume\n";
    return StopSignals::exit_code(sig);
  };
}

}  // namespace vob
