#include "harness/cli/raster_option.h"

#include <string>

#include "harness/scene/input_error.h"

namespace vob {

void RasterOption::add_to(CLI::App& cmd) {
  cmd.add_option_function<std::string>(
         "--raster",
         [this](const std::string& v) {
           rule_ = parse_raster_rule(v, "--raster");
           given_ = true;
         },
         "sampling rule of the oracle: exact (default) or gl (llvmpipe's coverage and 24-bit "
         "depth, pixel centres; triangle scenes); run/reproduce: instead of the suites' \"raster\"")
      ->check(CLI::IsMember({"exact", "gl"}))
      ->type_name("RULE");
}

void RasterOption::apply(SuiteSpec& suite) const {
  if (!given_) return;
  if (rule_ == RasterRule::gl && suite.supersample != 1)
    throw InputError("--raster gl", "suite " + suite.name, "samples pixel centres only, the suite has supersample " +
                                                              std::to_string(suite.supersample));
  suite.raster = rule_;
}

void RasterOption::apply(Reproduction& rep) const {
  for (SuiteSpec& s : rep.suites) apply(s);
}

}  // namespace vob
