// vobench reproduce NAME: run one experiment into reports/out/NAME (or -o DIR).
#include <filesystem>
#include <iostream>

#include "harness/cli/commands.h"
#include "harness/cli/experiments.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_reproduce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("reproduce", "run a paper experiment (see: vobench list)");
  auto name = std::make_shared<std::string>();
  auto ctx = std::make_shared<ExperimentContext>();
  cmd->add_option("name", *name, "experiment")->required();
  cmd->add_option("-o,--output", ctx->out_dir, "output folder (default reports/out/NAME)");
  cmd->add_flag("--resume", ctx->resume, "keep records already in the results file");
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
        return status == 0 ? 0 : 2;
      }
    std::string all;
    for (const auto& e : experiment_registry()) all += (all.empty() ? "" : ", ") + e.name;
    throw InputError("experiment", "'" + *name + "'", "is not known (known: " + all + ")");
  };
}

}  // namespace vob
