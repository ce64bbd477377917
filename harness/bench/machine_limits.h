// The machine's limits, measured: STREAM-triad bandwidth (a[i] = b[i] + s*c[i], 3 x 8 bytes
// counted per element) and the random-gather rate (sum of x[idx[i]], idx distinct random
// positions), over arrays much larger than the last-level cache, per thread count (TBB
// parallel loops inside a task_arena, so `--threads` caps them). Best of a few short
// repetitions. Measured once per run into the context line (context.cpp) and as the probe
// `machine-limits`; reports divide a record's working set by the triad rate at its thread
// count (docs/pipeline.md "Records").
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/probe.h"

namespace vob {

struct MachineLimitsOptions {
  size_t footprint_bytes = 0;  // the triad's 3 arrays together; 0: 4 x the last-level cache, >= 64 MiB
  int64_t gathers = 0;         // per timed pass; 0: 2^19 (at most a quarter of the array)
  int repetitions = 3;         // timed passes per thread count; the best counts
  int warmup = 0;              // untimed passes per thread count
};

// The last-level cache of cpu0 in bytes (sysfs), 0 when unknown.
size_t last_level_cache_bytes();

// {"triad": [{"threads", "bytes_per_second", "best_seconds", "median_seconds"}],
//  "gather": [{"threads", "gathers_per_second", "best_seconds", "median_seconds"}],
//  "triad_elements", "triad_bytes_per_pass", "gather_array_bytes", "gathers" (per pass),
//  "llc_bytes", "huge_pages" (the kernel took MADV_HUGEPAGE), "repetitions", "warmup",
//  "setup_seconds" (allocation, first touch), "first_touch" ({small_pages_bytes_per_second,
//  huge_pages_bytes_per_second, bytes}: fresh memory touched once per 4 KiB, on 4 KiB and on
//  2 MiB pages, 32 MiB each), "seconds" (wall time of the whole measurement)}.
// `thread_counts`: deduplicated, each run inside a task_arena of that many threads.
nlohmann::json measure_machine_limits(std::vector<int> thread_counts, const MachineLimitsOptions& opt = {});

// VOBENCH_MACHINE_LIMITS=skip in the environment: runs leave the measurement out of their
// context (for tests that start vobench many times; reports then say "not measured").
bool machine_limits_skipped();

// The probe `machine-limits`: the same measurement at 1 thread and the job's thread count.
ProbeInfo machine_limits_probe_info();

}  // namespace vob
