// vobench reproduce NAME: run a reproduction file (datasets/suites/**/NAME.json) into
// reports/out/NAME (installed: ./vobench-out/NAME; or -o DIR) and build its tables
// (docs/pipeline.md). `vobench reproduce all`: every reproduction with a paper into one
// folder (reports/out/all[-SCALE]), then the summary of every claim.
#include <csignal>
#include <filesystem>
#include <iostream>

#include "harness/bench/names.h"
#include "harness/bench/reproduction.h"
#include "harness/bench/resources.h"
#include "harness/cli/commands.h"
#include "harness/cli/python_script.h"
#include "harness/cli/reproduce.h"
#include "harness/cli/stop_signals.h"
#include "harness/cli/thread_option.h"
#include "harness/cli/raster_option.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// The exit status of a finished reproduction: stopped runs keep the shell's 128 + signal.
int exit_status(int status) {
  if (status == StopSignals::exit_code(SIGINT) || status == StopSignals::exit_code(SIGTERM)) return status;
  return status == 0 ? 0 : 2;
}

[[noreturn]] void unknown_reproduction(const std::string& name, const std::string& suites_dir) {
  std::vector<std::string> names;
  for (const auto& r : list_reproductions(suites_dir)) names.push_back(r.name);
  throw InputError("reproduction", "'" + name + "'", "is not known (" + known_names_hint(name, names) + ")");
}
}  // namespace

Command add_reproduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("reproduce", "run a reproduction and build its tables (see: vobench list)");
  auto name = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>();
  auto force = std::make_shared<bool>(false);
  auto full = std::make_shared<bool>(false);
  auto tiny = std::make_shared<bool>(false);
  cmd->add_option("name", *name, "reproduction, or 'all' (every reproduction with a paper, and the claims summary)")
      ->required();
  cmd->add_option("-o,--output", *out_dir,
                  "output folder (default reports/out/NAME, NAME-tiny or NAME-full in the source "
                  "tree; installed: the same names under ./vobench-out/)");
  cmd->add_flag("--force", *force,
                "start afresh: drop the records (and images) of an earlier run in the output folder; "
                "without it a rerun keeps them and computes only what is missing");
  auto* full_flag = cmd->add_flag("--full", *full, "the paper's full sizes where they are opt-in");
  cmd->add_flag("--tiny", *tiny, "the smallest sizes (seconds; the repro tests)")->excludes(full_flag);
  auto dry_run = std::make_shared<bool>(false);
  cmd->add_flag("--dry-run", *dry_run,
                "list the jobs (those already in the output folder marked) with their estimated cost "
                "and exit; makes no scene, writes nothing");
  auto format = std::make_shared<std::string>("jsonl");
  cmd->add_option("--format", *format,
                  "jsonl (default); gbench: also Google Benchmark's JSON of the folder's records "
                  "(DIR/results.gbench.json)")
      ->check(CLI::IsMember({"jsonl", "gbench"}));
  auto threads = std::make_shared<ThreadOption>();
  threads->add_to(*cmd);
  auto raster = std::make_shared<RasterOption>();
  raster->add_to(*cmd);
  return [=]() {
    const auto limit = threads->limit();
    // Google Benchmark's JSON of the finished folder, beside its results.jsonl.
    const auto with_format = [=](int status, const std::string& folder) {
      if (status != 0 || *format != "gbench") return status;
      const std::string results = folder + "/results.jsonl";
      return run_python_script("gbench.py", {results, "-o", gbench_path(results)});
    };
    std::error_code ec;
    if (!out_dir->empty() && std::filesystem::exists(*out_dir, ec) && !std::filesystem::is_directory(*out_dir, ec))
      throw InputError("--output", "'" + *out_dir + "'", "exists and is not a folder");
    const std::string suites_dir = resource_path("datasets/suites");
    const std::string scale = *tiny ? "tiny" : *full ? "full" : "default";
    std::string out = *out_dir;
    // Installed, nothing is written into the prefix: ./vobench-out/NAME instead.
    if (out.empty())
      out = (installed() ? std::string("vobench-out") : resource_path("reports/out")) + "/" + *name +
            (scale == "default" ? "" : "-" + scale);
    if (*name == "all" && find_reproduction(suites_dir, "all").empty()) {
      std::vector<Reproduction> reps;  // every file validated before any work
      for (const auto& e : list_reproductions(suites_dir)) {
        Reproduction rep = load_reproduction(e.path, scale, suites_dir);
        threads->apply(rep);
        raster->apply(rep);
        if (!rep.paper.empty()) reps.push_back(std::move(rep));
      }
      if (*dry_run) {
        dry_run_reproductions(reps, out, *force);
        return 0;
      }
      const int status = with_format(reproduce_all(reps, out, *force), out);
      if (status == 0) std::cerr << "reproduce all: wrote " << out << "/claims-summary.md\n";
      return exit_status(status);
    }
    const std::string path = find_reproduction(suites_dir, *name);
    if (path.empty()) unknown_reproduction(*name, suites_dir);
    Reproduction rep = load_reproduction(path, scale, suites_dir);  // every suite, before any work
    threads->apply(rep);
    raster->apply(rep);
    if (*dry_run) {
      dry_run_reproductions({rep}, out, *force);
      return 0;
    }
    const int status = with_format(reproduce(rep, out, *force), out);
    if (status == 0) std::cerr << "reproduce " << *name << ": wrote " << out << "/" << *name << ".md\n";
    return exit_status(status);
  };
}

}  // namespace vob
