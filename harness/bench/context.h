// The context record of a run, in the style of Google Benchmark's JSON "context":
// date, host, CPU, cores, compiler, build type, git sha.
#pragma once
#include <nlohmann/json.hpp>

namespace vob {
nlohmann::json run_context();
}
