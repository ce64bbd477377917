#include "harness/cli/experiments.h"

#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/runner.h"
#include "harness/cli/stop_signals.h"
#include "harness/scene/input_error.h"

extern char** environ;

namespace vob {

int run_report(const std::vector<std::string>& results, const std::string& out_dir,
               const std::string& title, const std::string& name,
               const std::vector<std::string>& include_md) {
  std::vector<std::string> args = {VOB_PYTHON, std::string(VOB_SOURCE_DIR) + "/reports/report.py",
                                   "--out", out_dir, "--title", title};
  if (!name.empty()) args.insert(args.end(), {"--name", name});
  for (const auto& m : include_md) args.insert(args.end(), {"--include", m});
  args.insert(args.end(), results.begin(), results.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw InputError(VOB_PYTHON, "report", "cannot start Debian's python3 (install python3-matplotlib)");
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 2;
}

int run_suite_experiment(const std::vector<std::string>& suite_files, const std::string& name,
                         const std::string& title, const ExperimentContext& ctx) {
  namespace fs = std::filesystem;
  std::vector<SuiteSpec> suites;  // all parsed before anything runs: a bad file fails fast
  for (const auto& f : suite_files)
    suites.push_back(SuiteSpec::load(std::string(VOB_SOURCE_DIR) + "/datasets/suites/" + f));
  require_writable_folder(ctx.out_dir);
  const std::string results = (fs::path(ctx.out_dir) / "results.jsonl").string();
  if (ctx.force) {
    std::error_code ec;
    fs::remove(results, ec);
    if (!ec) fs::remove_all(fs::path(ctx.out_dir) / "images", ec);
    if (ec) throw InputError(ctx.out_dir, "folder", "cannot be cleared (--force): " + ec.message());
  }
  const StopSignals signals;
  RunOptions opt;
  opt.results_path = results;
  opt.stop_requested = [] { return StopSignals::received() != 0; };
  const auto t0 = std::chrono::steady_clock::now();
  opt.progress = [t0](const std::string& line) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "[%6.1f s] %s\n", s, line.c_str());
  };
  for (const SuiteSpec& suite : suites) {
    std::fprintf(stderr, "suite %s\n", suite.name.c_str());
    const RunSummary r = run_suite(suite, opt);
    std::cerr << suite.name << ": " << r.written << " records written, " << r.skipped << " kept, ";
    if (r.written_elsewhere) std::cerr << r.written_elsewhere << " written meanwhile by another run, ";
    std::cerr << r.violations << " with oracle violations\n";
    if (r.stopped) {
      const int sig = StopSignals::received();
      std::cerr << name << ": stopped by " << StopSignals::name(sig) << "; every finished record is in "
                << results << ": run the same command again to resume\n";
      return StopSignals::exit_code(sig);
    }
  }
  return run_report({results}, ctx.out_dir, title, name);
}

}  // namespace vob
