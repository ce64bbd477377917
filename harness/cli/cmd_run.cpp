// vobench run: run a suite and append its records to a results file (JSONL).
#include <filesystem>
#include <iostream>

#include "harness/bench/runner.h"
#include "harness/cli/commands.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "run a suite (datasets/suites/*.json) into RESULTS.jsonl");
  auto suite = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("suite", *suite, "suite JSON")->required();
  cmd->add_option("-o,--output", *out, "results file (JSONL); existing records are skipped")->required();
  return [=]() {
    const SuiteSpec s = SuiteSpec::load(*suite);
    std::error_code ec;
    if (std::filesystem::exists(*out, ec) && !std::filesystem::is_regular_file(*out, ec))
      throw InputError("--output", "'" + *out + "'", "exists and is not a results file");
    RunOptions opt;
    opt.results_path = *out;
    opt.progress = [](const std::string& line) { std::cerr << line << std::endl; };
    const RunSummary r = run_suite(s, opt);
    std::cerr << "run " << s.name << ": " << r.written << " records written, " << r.skipped
              << " already present, " << r.violations << " with oracle violations -> " << *out << "\n";
    return 0;
  };
}

}  // namespace vob
