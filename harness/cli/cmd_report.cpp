// vobench report: results files -> Markdown + HTML with figures.
#include <filesystem>

#include "harness/cli/commands.h"
#include "harness/cli/experiments.h"
#include "harness/cli/report_input.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_report_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "turn results (JSONL) into Markdown + HTML with figures");
  auto results = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  auto title = std::make_shared<std::string>("vobench report");
  cmd->add_option("results", *results, "results files")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", *out, "output folder")->required();
  cmd->add_option("--title", *title, "report title");
  return [=]() {
    check_report_inputs(*results);
    std::error_code ec;
    if (std::filesystem::exists(*out, ec) && !std::filesystem::is_directory(*out, ec))
      throw InputError("--output", "'" + *out + "'", "exists and is not a folder");
    return run_report(*results, *out, *title, "") == 0 ? 0 : 2;
  };
}

}  // namespace vob
