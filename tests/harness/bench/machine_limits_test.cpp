// The machine's limits in the run context and as the probe machine-limits: present, positive,
// finite, at the thread counts the run may use; left out under VOBENCH_MACHINE_LIMITS=skip.
// Values only, never a speed: the machine is shared.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "harness/bench/context.h"
#include "harness/bench/jobs.h"
#include "harness/bench/machine_limits.h"
#include "harness/bench/probe.h"

namespace vob {
namespace {

// Every entry of `kind` has a positive finite `field` and best <= median; returns its threads.
std::set<int> check_entries(const nlohmann::json& ml, const char* kind, const char* field) {
  std::set<int> threads;
  EXPECT_TRUE(ml.contains(kind) && ml[kind].is_array() && !ml[kind].empty()) << ml.dump();
  for (const auto& e : ml[kind]) {
    const double v = e.at(field).get<double>();
    EXPECT_TRUE(std::isfinite(v) && v > 0) << kind << ": " << e.dump();
    EXPECT_GT(e.at("best_seconds").get<double>(), 0.0);
    EXPECT_LE(e.at("best_seconds").get<double>(), e.at("median_seconds").get<double>());
    threads.insert(e.at("threads").get<int>());
  }
  return threads;
}

class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() { had_ ? setenv(name_, old_.c_str(), 1) : unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

TEST(MachineLimits, ContextCarriesTriadAndGatherAtOneAndAllThreads) {
  unsetenv("VOBENCH_MACHINE_LIMITS");
  const nlohmann::json c = run_context(1);
  ASSERT_TRUE(c.contains("machine_limits")) << c.dump();
  const nlohmann::json& ml = c["machine_limits"];
  const std::set<int> want = {1, run_threads()};
  EXPECT_EQ(check_entries(ml, "triad", "bytes_per_second"), want);
  EXPECT_EQ(check_entries(ml, "gather", "gathers_per_second"), want);
  // Arrays much larger than the last-level cache, when sysfs names one.
  const size_t llc = ml["llc_bytes"].get<size_t>();
  EXPECT_GE(ml["triad_bytes_per_pass"].get<size_t>(), std::max<size_t>(4 * llc, size_t(64) << 20) - 24);
  EXPECT_GE(ml["gather_array_bytes"].get<size_t>() * 2, std::max<size_t>(4 * llc, size_t(64) << 20));
  EXPECT_GT(ml["seconds"].get<double>(), 0.0);
  EXPECT_GE(ml["repetitions"].get<int>(), 1);
  // The first-touch rates of fresh 4 KiB and 2 MiB pages, 32 MiB each.
  const nlohmann::json& ft = ml["first_touch"];
  ASSERT_TRUE(ft.is_object()) << ml.dump();
  EXPECT_EQ(ft["bytes"].get<size_t>(), size_t(32) << 20);
  for (const char* k : {"small_pages_bytes_per_second", "huge_pages_bytes_per_second"}) {
    const double v = ft.at(k).get<double>();
    EXPECT_TRUE(std::isfinite(v) && v > 0) << k << ": " << ft.dump();
  }
}

TEST(MachineLimits, ThreadLimitCapsTheAllThreadsCount) {
  // `--threads 1` holds this limit for the command: nothing is measured above it.
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const nlohmann::json ml = measure_machine_limits({1, 4, 8}, {size_t(3) << 20, 1 << 12, 1, 0});
  EXPECT_EQ(check_entries(ml, "triad", "bytes_per_second"), std::set<int>{1});
  EXPECT_EQ(check_entries(ml, "gather", "gathers_per_second"), std::set<int>{1});
  EXPECT_EQ(ml["gathers"].get<int64_t>(), 1 << 12);
  EXPECT_EQ(ml["triad_elements"].get<size_t>(), (size_t(3) << 20) / 24);
}

TEST(MachineLimits, GathersAreCappedByTheArray) {
  const nlohmann::json ml = measure_machine_limits({1}, {size_t(1) << 20, int64_t(1) << 30, 1, 0});
  // x = 3 * (2^20 / 24) = 131070 doubles: positions within 2^16, the largest power of two not
  // above, in 4 windows of 2^14.
  EXPECT_EQ(ml["gathers"].get<int64_t>(), int64_t(1) << 14);
}

TEST(MachineLimits, SkippedUnderTheEnvironmentSwitch) {
  ScopedEnv env("VOBENCH_MACHINE_LIMITS", "skip");
  EXPECT_TRUE(machine_limits_skipped());
  EXPECT_FALSE(run_context(1).contains("machine_limits"));
}

TEST(MachineLimits, ProbeRecordsTheSameMeasurement) {
  const ProbeInfo& info = find_probe("machine-limits");
  EXPECT_FALSE(info.needs_scene);
  Params dry("probe machine-limits");
  dry.set("mib", "4");
  dry.set_dry_run(true);
  EXPECT_TRUE(info.run(dry, ProbeContext{}).empty());
  Params p("probe machine-limits");
  p.set("mib", "4");
  p.set("gathers_log2", "12");
  ProbeContext ctx;
  ctx.repeats = 2;
  ctx.warmup = 0;
  const nlohmann::json r = info.run(p, ctx);
  p.check_all_used();
  EXPECT_EQ(check_entries(r, "triad", "bytes_per_second"), (std::set<int>{1, run_threads()}));
  EXPECT_EQ(check_entries(r, "gather", "gathers_per_second"), (std::set<int>{1, run_threads()}));
  EXPECT_EQ(r["repetitions"].get<int>(), 2);
  EXPECT_EQ(r["triad_bytes_per_pass"].get<size_t>(), (size_t(4) << 20) / 24 * 24);
}

}  // namespace
}  // namespace vob
