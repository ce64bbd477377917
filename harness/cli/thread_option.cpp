#include "harness/cli/thread_option.h"

#include <string>

#include "harness/cli/scene_args.h"

namespace vob {

void ThreadOption::add_to(CLI::App& cmd) {
  cmd.add_option("--threads", threads_,
                 "TBB threads for everything this command times (0: all cores, up to " +
                     std::to_string(kMaxThreads) + "); run/reproduce: instead of the suites' \"threads\"")
      ->check(integer_in(0, kMaxThreads))
      ->type_name("N");
}

std::unique_ptr<tbb::global_control> ThreadOption::limit() const {
  if (threads_ <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads_);
}

void ThreadOption::apply(SuiteSpec& suite) const {
  if (given()) suite.threads = {threads_};
}

void ThreadOption::apply(Reproduction& rep) const {
  for (SuiteSpec& s : rep.suites) apply(s);
}

}  // namespace vob
