#include "harness/bench/context.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

namespace vob {

namespace {
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}
// The sha of the source tree now (not at configure time), with "+dirty" for local edits.
std::string git_sha() {
  const std::string cmd = std::string("git -C '") + VOB_SOURCE_DIR +
                          "' describe --always --dirty=+dirty 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "";
  char buf[128] = "";
  const bool got = fgets(buf, sizeof buf, p) != nullptr;
  pclose(p);
  std::string s = got ? buf : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}
}  // namespace

nlohmann::json run_context() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"date", date},
          {"host_name", host},
          {"cpu", cpu_model()},
          {"num_cpus", std::thread::hardware_concurrency()},
          {"compiler", VOB_COMPILER},
          {"build_type", VOB_BUILD_TYPE},
          {"git_sha", git_sha()}};
}

}  // namespace vob
