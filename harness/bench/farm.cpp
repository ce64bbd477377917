#include "harness/bench/farm.h"

#include <dlfcn.h>

#include <filesystem>

namespace vob {

std::vector<JobGroup> plan_groups(const std::vector<FarmSuite>& suites, const KnownRecords& known,
                                  const RecordedTimes& times) {
  std::vector<JobGroup> groups;
  for (size_t i = 0; i < suites.size(); ++i)
    add_groups(groups, i, suites[i].tags.suite_name(suites[i].suite), plan_run(suites[i].suite, suites[i].tags, known),
               times);
  return groups;
}

std::string failures_path(const std::string& results_path) {
  std::filesystem::path p(results_path);
  const std::string stem = p.extension() == ".jsonl" ? p.stem().string() : p.filename().string();
  return (p.parent_path() / (stem + ".failed.jsonl")).string();
}

std::string farm_module_path() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&farm_module_path), &info) == 0 || !info.dli_fname) return "";
  return (std::filesystem::path(info.dli_fname).parent_path() / "libvobench-mpi.so").string();
}

}  // namespace vob
