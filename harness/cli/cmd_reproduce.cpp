// vobench reproduce NAME: run a reproduction file (datasets/suites/**/NAME.json) into
// reports/out/NAME (or -o DIR) and build its tables; names no file knows yet fall back to
// the C++ experiments of experiment_registry.cpp while they are being converted.
#include <csignal>
#include <filesystem>
#include <iostream>

#include "harness/bench/reproduction.h"
#include "harness/cli/commands.h"
#include "harness/cli/experiments.h"
#include "harness/cli/reproduce.h"
#include "harness/cli/stop_signals.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// The exit status of a finished reproduction: stopped runs keep the shell's 128 + signal.
int exit_status(int status) {
  if (status == StopSignals::exit_code(SIGINT) || status == StopSignals::exit_code(SIGTERM)) return status;
  return status == 0 ? 0 : 2;
}

int run_old_experiment(const std::string& name, ExperimentContext c, bool tiny) {
  for (const auto& e : experiment_registry())
    if (e.name == name) {
      if (tiny) throw InputError("--tiny", name, "has no tiny scale (a C++ experiment not yet converted)");
      if (c.out_dir.empty()) c.out_dir = std::string(VOB_SOURCE_DIR) + "/reports/out/" + name;
      const int status = e.run(c);
      if (status == 0) std::cerr << "reproduce " << name << ": wrote " << c.out_dir << "/" << name << ".md\n";
      return exit_status(status);
    }
  std::string all;
  for (const auto& r : list_reproductions(std::string(VOB_SOURCE_DIR) + "/datasets/suites"))
    all += (all.empty() ? "" : ", ") + r.name;
  for (const auto& e : experiment_registry()) all += (all.empty() ? "" : ", ") + e.name;
  throw InputError("reproduction", "'" + name + "'", "is not known (known: " + all + ")");
}
}  // namespace

Command add_reproduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("reproduce", "run a reproduction and build its tables (see: vobench list)");
  auto name = std::make_shared<std::string>();
  auto ctx = std::make_shared<ExperimentContext>();
  auto tiny = std::make_shared<bool>(false);
  cmd->add_option("name", *name, "reproduction")->required();
  cmd->add_option("-o,--output", ctx->out_dir,
                  "output folder (default reports/out/NAME, NAME-tiny or NAME-full)");
  cmd->add_flag("--force", ctx->force,
                "start afresh: drop the records (and images) of an earlier run in the output folder; "
                "without it a rerun keeps them and computes only what is missing");
  auto* full = cmd->add_flag("--full", ctx->full, "the paper's full sizes where they are opt-in");
  cmd->add_flag("--tiny", *tiny, "the smallest sizes (seconds; the repro tests)")->excludes(full);
  return [=]() {
    std::error_code ec;
    if (!ctx->out_dir.empty() && std::filesystem::exists(ctx->out_dir, ec) &&
        !std::filesystem::is_directory(ctx->out_dir, ec))
      throw InputError("--output", "'" + ctx->out_dir + "'", "exists and is not a folder");
    const std::string suites_dir = std::string(VOB_SOURCE_DIR) + "/datasets/suites";
    const std::string path = find_reproduction(suites_dir, *name);
    if (path.empty()) return run_old_experiment(*name, *ctx, *tiny);
    const std::string scale = *tiny ? "tiny" : ctx->full ? "full" : "default";
    const Reproduction rep = load_reproduction(path, scale, suites_dir);  // every suite, before any work
    std::string out = ctx->out_dir;
    if (out.empty())
      out = std::string(VOB_SOURCE_DIR) + "/reports/out/" + *name + (scale == "default" ? "" : "-" + scale);
    const int status = reproduce(rep, out, ctx->force);
    if (status == 0) std::cerr << "reproduce " << *name << ": wrote " << out << "/" << *name << ".md\n";
    return exit_status(status);
  };
}

}  // namespace vob
