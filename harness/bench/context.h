// The context of a run, in the style of Google Benchmark's JSON "context": date, host, CPU
// (model, MHz, caches), cores, threads, load average at the start, compiler, build type,
// git sha, library versions, and the machine's streaming and gather limits. Written once per
// run as a context line of results.jsonl (docs/pipeline.md "Records"); the run's records
// carry its run_id.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace vob {
// Unique per run: UTC date-time, host, pid and a random part ("20261202T054800Z-h-123-a1b2c3").
std::string new_run_id();
// `threads`: the TBB parallelism the run measures with. Includes `machine_limits`
// (machine_limits.h; 0.45 to 3.3 s on 2 loaded cores) unless VOBENCH_MACHINE_LIMITS=skip.
nlohmann::json run_context(int threads);
// How the process allocates large blocks, recorded in every run context as "allocation"
// (the vobench program sets it at start: harness/cli/huge_page_new.h). Unset: plain malloc.
void set_allocation_context(const nlohmann::json& allocation);
// {"key": "context|RUN_ID", "type": "context", "run_id", "schema_version", "context"}.
nlohmann::json context_line(const std::string& run_id, const nlohmann::json& context);
bool is_context_line(const nlohmann::json& j);
}  // namespace vob
