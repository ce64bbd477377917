// `--raster exact|gl` of the subcommands that judge images (check, order, run, reproduce):
// the oracle's sampling rule (harness/raster/raster_rule.h). For run and reproduce it
// replaces each suite's "raster", so keys and records say which rule judged them.
#pragma once
#include <CLI/CLI.hpp>

#include "harness/bench/reproduction.h"
#include "harness/bench/suite.h"
#include "harness/raster/raster_rule.h"

namespace vob {

class RasterOption {
 public:
  // Adds the option; another value than exact or gl is a parse error (one line, exit 2).
  void add_to(CLI::App& cmd);
  bool given() const { return given_; }
  RasterRule rule() const { return rule_; }
  void apply(SuiteSpec& suite) const;
  void apply(Reproduction& rep) const;

 private:
  RasterRule rule_ = RasterRule::exact;
  bool given_ = false;
};

}  // namespace vob
