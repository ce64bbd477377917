// `--threads N` of the subcommands that measure or order (run, reproduce, check, order): the
// TBB parallelism for the command's lifetime (0: all cores). For run and reproduce it also
// replaces each suite's `threads` list with {N}, so keys and records say N.
#pragma once
#include <memory>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include "harness/bench/reproduction.h"
#include "harness/bench/suite.h"

namespace vob {

class ThreadOption {
 public:
  // Adds the option; a value that is not an integer in [0, kMaxThreads] is a parse error
  // (one line, exit 2).
  void add_to(CLI::App& cmd);
  bool given() const { return threads_ >= 0; }
  // The limit to hold while the command runs; null when not given or 0.
  std::unique_ptr<tbb::global_control> limit() const;
  void apply(SuiteSpec& suite) const;
  void apply(Reproduction& rep) const;

 private:
  int threads_ = -1;
};

}  // namespace vob
