// vobench compare BASE.jsonl NEW.jsonl: time ratios with a Mann-Whitney U test on the
// per-repeat samples, and correctness changes, per matched record (reports/compare.py does
// the work; docs/pipeline.md "vobench compare"). Exit 1 on a regression (a base record
// missing from new included), 2 on bad input or when nothing matches.
#include <sstream>

#include "harness/cli/commands.h"
#include "harness/cli/python_script.h"

namespace vob {

Command add_compare_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("compare", "compare two results files: time ratios, U test, correctness changes");
  struct Opts {
    std::string base, fresh, out;
    double threshold = 0.10, alpha = 0.05, pixel_growth = 0.10, min_ms = 0.05;
    int pixel_slack = 10;
    bool allow = false, allow_missing = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("base", o->base, "the baseline results.jsonl")->required()->check(CLI::ExistingFile);
  cmd->add_option("new", o->fresh, "the results.jsonl to judge against it")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->out, "also write FILE.md or FILE.html");
  cmd->add_option("--threshold", o->threshold, "slowdown that counts, as a fraction (default 0.10)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--min-ms", o->min_ms, "a slowdown below this many ms per frame is noise (default 0.05)")
      ->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--alpha", o->alpha, "U-test significance level (default 0.05)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--pixel-growth", o->pixel_growth,
                  "a heuristic's violating-pixel growth that counts, as a fraction (default 0.10)")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--pixel-slack", o->pixel_slack, "... and in pixels (default 10)")->check(CLI::Range(0, 1 << 30));
  cmd->add_flag("--allow-different-settings", o->allow, "compare records made with different settings");
  cmd->add_flag("--allow-missing", o->allow_missing,
                "base records absent from new are not a regression (new is meant to be a subset)");
  return [o]() {
    auto num = [](double v) {
      std::ostringstream s;
      s << v;
      return s.str();
    };
    std::vector<std::string> args = {o->base, o->fresh, "--threshold", num(o->threshold), "--alpha", num(o->alpha), "--min-ms", num(o->min_ms),
                                     "--pixel-growth", num(o->pixel_growth), "--pixel-slack",
                                     std::to_string(o->pixel_slack)};
    if (!o->out.empty()) args.insert(args.end(), {"-o", o->out});
    if (o->allow) args.push_back("--allow-different-settings");
    if (o->allow_missing) args.push_back("--allow-missing");
    return run_python_script("compare.py", args);
  };
}

}  // namespace vob
