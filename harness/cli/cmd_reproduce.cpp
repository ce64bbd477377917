// vobench reproduce NAME: run a reproduction file (datasets/suites/**/NAME.json) into
// reports/out/NAME (installed: ./vobench-out/NAME; or -o DIR) and build its tables
// (docs/pipeline.md). `vobench reproduce all`: every reproduction with a paper into one
// folder (reports/out/all[-SCALE]), then the summary of every claim.
#include <csignal>
#include <filesystem>
#include <iostream>

#include "harness/bench/names.h"
#include "harness/bench/runner.h"
#include "harness/bench/reproduction.h"
#include "harness/bench/resources.h"
#include "harness/cli/commands.h"
#include "harness/cli/python_script.h"
#include "harness/cli/reproduce.h"
#include "harness/cli/shard.h"
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

std::vector<FarmSuite> farm_suites(const std::vector<Reproduction>& reps) {
  std::vector<FarmSuite> suites;
  for (const Reproduction& rep : reps)
    for (const SuiteSpec& s : rep.suites) suites.push_back({s, RunTags{rep.name, rep.paper, rep.scale}});
  return suites;
}

// --shard I/N: the part of the reproductions' jobs this shard runs (none: all).
RunPart shard_part(const std::vector<Reproduction>& reps, const SpreadOptions& spread) {
  RunPart part;
  if (!spread.sharded()) return part;
  part.take_group = shard_filter(farm_suites(reps), spread, std::cerr);
  part.placement = lone_placement();
  part.placement["shard"] = spread.shard_text();
  return part;
}

int spread_dry_run(const std::vector<Reproduction>& reps, const std::string& out, bool force,
                   const SpreadOptions& spread) {
  dry_run_reproductions(reps, out, force, spread.costs);
  if (spread.sharded()) shard_filter(farm_suites(reps), spread, std::cout);
  if (spread.ranks > 0) {
    const std::string results = out + "/results.jsonl";
    const std::string from = spread.costs.empty() ? results : spread.costs;
    const KnownRecords known = force ? KnownRecords() : KnownRecords::read(results);
    const RecordedTimes times = RecordedTimes::read(from);
    print_makespan(std::cout, plan_groups(farm_suites(reps), known, times), spread.ranks, times, from);
  }
  return 0;
}

// --mpi: the reproductions' suites as one farm into OUT/results.jsonl; rank 0 prepares the
// folder first and builds the tables after (`tables`).
int farm_reproductions(const std::vector<Reproduction>& reps, const std::string& out, bool force,
                       const SpreadOptions& spread, std::function<int(int)> tables) {
  const StopSignals signals;
  FarmRequest req;
  req.name = "reproduce " + (reps.size() == 1 ? reps.front().name : std::string("all"));
  req.suites = farm_suites(reps);
  req.results_path = out + "/results.jsonl";
  req.costs_path = spread.costs;
  req.pin = spread.pin;
  req.stop_signal = [] { return StopSignals::received(); };
  req.before = [=] { prepare_folder(reps, out, force); };
  req.after = std::move(tables);
  return run_farm(req);
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
                "start afresh: drop this reproduction's records (and their images) from the output "
                "folder, keeping other reproductions' records there; without it a rerun keeps them "
                "and computes only what is missing");
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
  auto spread = std::make_shared<SpreadOptions>();
  spread->add_to(*cmd);
  auto raster = std::make_shared<RasterOption>();
  raster->add_to(*cmd);
  return [=]() {
    spread->check(*dry_run);
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
            (scale == "default" ? "" : "-" + scale) +
            (spread->sharded() ? "-shard" + std::to_string(spread->index) + "of" + std::to_string(spread->count) : "");
    if (*name == "all" && find_reproduction(suites_dir, "all").empty()) {
      std::vector<Reproduction> reps;  // every file validated before any work
      for (const auto& e : list_reproductions(suites_dir)) {
        Reproduction rep = load_reproduction(e.path, scale, suites_dir);
        threads->apply(rep);
        raster->apply(rep);
        if (!rep.paper.empty()) reps.push_back(std::move(rep));
      }
      if (*dry_run) return spread_dry_run(reps, out, *force, *spread);
      if (spread->mpi)
        return exit_status(farm_reproductions(reps, out, *force, *spread, [=](int status) {
          const int tables = run_python_script("build_tables.py", {out});
          return with_format(status != 0 ? status : tables, out);
        }));
      const RunPart part = shard_part(reps, *spread);
      const int status = with_format(reproduce_all(reps, out, *force, &part), out);
      if (status == 0) std::cerr << "reproduce all: wrote " << out << "/claims-summary.md\n";
      return exit_status(status);
    }
    const std::string path = find_reproduction(suites_dir, *name);
    if (path.empty()) unknown_reproduction(*name, suites_dir);
    Reproduction rep = load_reproduction(path, scale, suites_dir);  // every suite, before any work
    threads->apply(rep);
    raster->apply(rep);
    if (*dry_run) return spread_dry_run({rep}, out, *force, *spread);
    if (spread->mpi)
      return exit_status(farm_reproductions({rep}, out, *force, *spread, [=](int status) {
        return with_format(status != 0 ? status : build_tables(rep, out), out);
      }));
    const RunPart part = shard_part({rep}, *spread);
    const int status = with_format(reproduce(rep, out, *force, nullptr, &part), out);
    if (status == 0) std::cerr << "reproduce " << *name << ": wrote " << out << "/" << *name << ".md\n";
    return exit_status(status);
  };
}

}  // namespace vob
