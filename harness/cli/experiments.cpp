#include "harness/cli/experiments.h"

#include <filesystem>

#include "harness/bench/runner.h"
#include "harness/cli/python_script.h"
#include "harness/cli/reproduce.h"

namespace vob {

int run_report(const std::vector<std::string>& results, const std::string& out_dir,
               const std::string& title, const std::string& name,
               const std::vector<std::string>& include_md) {
  std::vector<std::string> args = {"--out", out_dir, "--title", title};
  if (!name.empty()) args.insert(args.end(), {"--name", name});
  for (const auto& m : include_md) args.insert(args.end(), {"--include", m});
  args.insert(args.end(), results.begin(), results.end());
  return run_python_script("report.py", args);
}

int run_suite_experiment(const std::vector<std::string>& suite_files, const std::string& name,
                         const std::string& title, const ExperimentContext& ctx) {
  std::vector<SuiteSpec> suites;  // all parsed before anything runs: a bad file fails fast
  for (const auto& f : suite_files)
    suites.push_back(SuiteSpec::load(std::string(VOB_SOURCE_DIR) + "/datasets/suites/" + f));
  const int status = run_suites_into(suites, name, ctx.out_dir, ctx.force, RunTags{});
  if (status != 0) return status;
  return run_report({(std::filesystem::path(ctx.out_dir) / "results.jsonl").string()}, ctx.out_dir, title, name);
}

}  // namespace vob
