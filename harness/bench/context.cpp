#include "harness/bench/context.h"

#include <unistd.h>

#include <oneapi/tbb/version.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <thread>

#include "harness/bench/jobs.h"
#include "harness/bench/machine_limits.h"
#include "harness/bench/record.h"
#include "harness/bench/resources.h"

// Library versions the build was configured with (harness/bench/CMakeLists.txt).
#ifndef VOB_VTK_VERSION
#define VOB_VTK_VERSION ""
#endif
#ifndef VOB_CGAL_VERSION
#define VOB_CGAL_VERSION ""
#endif
#ifndef VOB_EMBREE_VERSION
#define VOB_EMBREE_VERSION ""
#endif
#ifndef VOB_OSMESA_VERSION
#define VOB_OSMESA_VERSION ""
#endif

namespace vob {

namespace {
// The value of the first "NAME : value" line of /proc/cpuinfo, or "".
std::string cpuinfo(const std::string& name) {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(name, 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos || colon + 2 > line.size() ? "" : line.substr(colon + 2);
    }
  return "";
}
std::string first_line(const std::string& path) {
  std::ifstream in(path);
  std::string s;
  std::getline(in, s);
  return s;
}
// Caches of cpu0 from sysfs ({level, type, size}); /proc/cpuinfo's "cache size" without it.
nlohmann::json caches() {
  nlohmann::json out = nlohmann::json::array();
  for (int i = 0; i < 16; ++i) {
    const std::string d = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/";
    const std::string size = first_line(d + "size");
    if (size.empty()) break;
    out.push_back({{"level", first_line(d + "level")}, {"type", first_line(d + "type")}, {"size", size}});
  }
  if (out.empty() && !cpuinfo("cache size").empty())
    out.push_back({{"level", "?"}, {"type", "cpuinfo"}, {"size", cpuinfo("cache size")}});
  return out;
}
std::string host_name() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  return host;
}
std::string utc_now(const char* format) {
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, format, std::gmtime(&now));
  return date;
}
}  // namespace

std::string new_run_id() {
  std::random_device rd;
  char rnd[16];
  std::snprintf(rnd, sizeof rnd, "%06x", unsigned(rd()) & 0xffffffu);
  std::string host = host_name();
  for (char& c : host)
    if (c == '|' || c == ' ') c = '_';  // the id is part of a key
  return utc_now("%Y%m%dT%H%M%SZ") + "-" + host + "-" + std::to_string(getpid()) + "-" + rnd;
}

namespace {
nlohmann::json& allocation_context() {
  static nlohmann::json a = {{"huge_pages", false}, {"why_off", "not the vobench program: plain malloc"}};
  return a;
}
}  // namespace

void set_allocation_context(const nlohmann::json& allocation) { allocation_context() = allocation; }

nlohmann::json run_context(int threads) {
  double load[3] = {-1, -1, -1};
  const bool have_load = getloadavg(load, 3) == 3;  // before the measurement below adds to it
  const std::string mhz = cpuinfo("cpu MHz");
  const std::string max_khz = first_line("/sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq");
  nlohmann::json c = {{"date", utc_now("%Y-%m-%dT%H:%M:%SZ")},
          {"host_name", host_name()},
          {"cpu", cpuinfo("model name").empty() ? "unknown" : cpuinfo("model name")},
          {"mhz", mhz.empty() ? nlohmann::json(nullptr) : nlohmann::json(std::atof(mhz.c_str()))},
          {"max_mhz", max_khz.empty() ? nlohmann::json(nullptr) : nlohmann::json(std::atof(max_khz.c_str()) / 1000)},
          {"caches", caches()},
          {"num_cpus", std::thread::hardware_concurrency()},
          {"threads", threads},
          {"load_avg", have_load ? nlohmann::json{load[0], load[1], load[2]} : nlohmann::json(nullptr)},
          {"compiler", VOB_COMPILER},
          {"build_type", VOB_BUILD_TYPE},
          {"git_sha", source_revision()},
          {"libraries",
           {{"vtk", VOB_VTK_VERSION},
            {"cgal", VOB_CGAL_VERSION},
            {"embree", VOB_EMBREE_VERSION},
            {"osmesa", VOB_OSMESA_VERSION},
            {"tbb", TBB_runtime_version()},
            {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                                  std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                                  std::to_string(NLOHMANN_JSON_VERSION_PATCH)}}}};
  c["allocation"] = allocation_context();
  // At 1 thread, the run's first count and all threads the run may use (`--threads`).
  if (!machine_limits_skipped()) c["machine_limits"] = measure_machine_limits({1, threads, run_threads()});
  return c;
}

nlohmann::json context_line(const std::string& run_id, const nlohmann::json& context) {
  return {{"key", "context|" + run_id},
          {"type", "context"},
          {"run_id", run_id},
          {"schema_version", kSchemaVersion},
          {"context", context}};
}

bool is_context_line(const nlohmann::json& j) {
  return j.is_object() && j.contains("type") && j["type"] == "context";
}

}  // namespace vob
