// vobench report DIR: every table, claim and figure of the reproductions whose records are
// in DIR/results.jsonl, and the generic report; vobench report FILES -o OUT: the generic
// report (Markdown + HTML with figures) of results files.
#include <filesystem>

#include "harness/bench/resources.h"
#include "harness/cli/commands.h"
#include "harness/cli/report_input.h"
#include "harness/cli/reproduce.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_report_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "report", "rebuild the tables of a results folder (DIR), or report results files (FILES -o OUT)");
  auto results = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  auto title = std::make_shared<std::string>("vobench report");
  cmd->add_option("results", *results, "a folder holding results.jsonl, or results files")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("-o,--output", *out, "output folder (results files only)");
  cmd->add_option("--title", *title, "report title (results files only)");
  return [=]() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (results->size() == 1 && fs::is_directory(results->front(), ec)) {
      if (!out->empty()) throw InputError("--output", "'" + *out + "'", "does not apply to a results folder (tables go into it)");
      const std::string dir = results->front();
      check_report_inputs({(fs::path(dir) / "results.jsonl").string()}, /*plans_suffice=*/true);
      return report_folder(dir, resource_path("datasets/suites")) == 0 ? 0 : 2;
    }
    for (const auto& r : *results)
      if (fs::is_directory(r, ec)) throw InputError(r, "results", "is a folder: give one folder alone, or results files");
    if (out->empty()) throw InputError("--output", "results files", "is required with results files");
    check_report_inputs(*results);
    if (fs::exists(*out, ec) && !fs::is_directory(*out, ec))
      throw InputError("--output", "'" + *out + "'", "exists and is not a folder");
    return run_report(*results, *out, *title, "") == 0 ? 0 : 2;
  };
}

}  // namespace vob
