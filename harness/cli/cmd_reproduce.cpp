// vobench reproduce NAME: run one experiment into reports/out/NAME (or -o DIR).
#include <filesystem>
#include <csignal>
#include <iostream>

#include "harness/cli/commands.h"
#include "harness/cli/experiments.h"
#include "harness/cli/stop_signals.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_reproduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("reproduce", "run a paper experiment (see: vobench list)");
  auto name = std::make_shared<std::string>();
  auto ctx = std::make_shared<ExperimentContext>();
  cmd->add_option("name", *name, "experiment")->required();
  cmd->add_option("-o,--output", ctx->out_dir, "output folder (default reports/out/NAME)");
  cmd->add_flag("--force", ctx->force,
                "start afresh: drop the records (and images) of an earlier run in the output folder; "
                "without it a rerun keeps them and computes only what is missing");
  cmd->add_flag("--full", ctx->full, "the paper's full sizes where they are opt-in");
  return [=]() {
    for (const auto& e : experiment_registry())
      if (e.name == *name) {
        ExperimentContext c = *ctx;
        if (c.out_dir.empty()) c.out_dir = std::string(VOB_SOURCE_DIR) + "/reports/out/" + *name;
        std::error_code ec;
        if (std::filesystem::exists(c.out_dir, ec) && !std::filesystem::is_directory(c.out_dir, ec))
          throw InputError("--output", "'" + c.out_dir + "'", "exists and is not a folder");
        const int status = e.run(c);
        if (status == 0) std::cerr << "reproduce " << *name << ": wrote " << c.out_dir << "/" << *name << ".md\n";
        // Stopped by SIGINT or SIGTERM: the shell's 128 + signal (see stop_signals.h).
        if (status == StopSignals::exit_code(SIGINT) || status == StopSignals::exit_code(SIGTERM)) return status;
        return status == 0 ? 0 : 2;
      }
    std::string all;
    for (const auto& e : experiment_registry()) all += (all.empty() ? "" : ", ") + e.name;
    throw InputError("experiment", "'" + *name + "'", "is not known (known: " + all + ")");
  };
}

}  // namespace vob
