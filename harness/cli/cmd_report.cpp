// vobench report: results files -> Markdown + HTML with figures.
#include "harness/cli/commands.h"
#include "harness/cli/experiments.h"

namespace vob {

Command add_report_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "turn results (JSONL) into Markdown + HTML with figures");
  auto results = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  auto title = std::make_shared<std::string>("vobench report");
  cmd->add_option("results", *results, "results files")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", *out, "output folder")->required();
  cmd->add_option("--title", *title, "report title");
  return [=]() { return run_report(*results, *out, *title, "") == 0 ? 0 : 2; };
}

}  // namespace vob
