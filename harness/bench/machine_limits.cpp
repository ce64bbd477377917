#include "harness/bench/machine_limits.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "harness/bench/jobs.h"

namespace vob {

namespace {
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// sysfs sizes read "32768K" or "1M".
size_t cache_size_bytes(const std::string& s) {
  if (s.empty()) return 0;
  size_t v = std::strtoull(s.c_str(), nullptr, 10);
  if (s.back() == 'K') v <<= 10;
  if (s.back() == 'M') v <<= 20;
  return v;
}

// A bijection of [0, 2^bits): xor-shifts and odd multiplies mod 2^bits each are one, so
// i -> position(i) is a random-looking permutation with no stride a prefetcher could follow.
uint64_t position(uint64_t i, int bits) {
  const uint64_t mask = (uint64_t(1) << bits) - 1;
  const int s = std::max(1, bits / 2);
  uint64_t h = i;
  h = (h * 0x9E3779B97F4A7C15ull) & mask;
  h ^= h >> s;
  h = (h * 0xC2B2AE3D27D4EB4Full) & mask;
  h ^= h >> s;
  h = (h * 0x165667B19E3779F9ull) & mask;
  h ^= h >> s;
  return h;
}

struct Timing {
  double best = 0, median = 0;
};
template <class F>
Timing time_passes(int warmup, int repetitions, F&& pass) {
  for (int i = 0; i < warmup; ++i) pass();
  std::vector<double> s;
  for (int i = 0; i < repetitions; ++i) {
    const auto t0 = Clock::now();
    pass();
    s.push_back(seconds_since(t0));
  }
  std::sort(s.begin(), s.end());
  return {s.front(), s[s.size() / 2]};
}

constexpr size_t kHugePage = size_t(2) << 20;
constexpr int kWindows = 4;  // gather passes rotate over this many disjoint position windows

struct FreeDeleter {
  void operator()(void* p) const { std::free(p); }
};

// The buffers: `buf` holds the triad's a, b, c one after the other and is the gather's x;
// `idx` holds kWindows windows of `gathers` positions, one window per pass in turn, so a pass
// does not find the lines of the one before in the cache.
struct Arrays {
  size_t n_triad = 0, n_x = 0;
  int x_bits = 0;
  std::unique_ptr<double, FreeDeleter> buf;
  std::unique_ptr<uint32_t[]> idx;
  int64_t gathers = 0;
  bool huge_pages = false;
  double* x() const { return buf.get(); }
};

Arrays make_arrays(size_t footprint, int64_t gathers) {
  Arrays a;
  a.n_triad = footprint / (3 * sizeof(double));
  a.n_x = 3 * a.n_triad;
  while ((size_t(1) << (a.x_bits + 1)) <= a.n_x) ++a.x_bits;  // positions within 2^x_bits <= n_x
  a.gathers = std::min<int64_t>(gathers, (int64_t(1) << a.x_bits) / kWindows);
  if (a.n_triad == 0 || a.gathers <= 0) throw std::invalid_argument("machine limits: footprint too small");
  // Transparent huge pages where the kernel gives them: a fault per 2 MiB instead of per
  // 4 KiB (most of the set-up), and a gather limited by memory rather than by page walks.
  const size_t bytes = (a.n_x * sizeof(double) + kHugePage - 1) / kHugePage * kHugePage;
  a.buf.reset(static_cast<double*>(std::aligned_alloc(kHugePage, bytes)));
  if (!a.buf) throw std::bad_alloc();
  a.huge_pages = madvise(a.buf.get(), bytes, MADV_HUGEPAGE) == 0;
  a.idx.reset(new uint32_t[kWindows * a.gathers]);
  double* x = a.x();
  uint32_t* idx = a.idx.get();
  const int bits = a.x_bits;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, a.n_x), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) x[i] = double(i & 1023);  // sums stay exact
  }, tbb::static_partitioner());
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, kWindows * a.gathers), [&](const tbb::blocked_range<int64_t>& r) {
    for (int64_t i = r.begin(); i < r.end(); ++i) idx[i] = uint32_t(position(uint64_t(i), bits));
  });
  return a;
}

void triad(Arrays& m) {
  const size_t n = m.n_triad;
  double* __restrict a = m.x();
  const double* __restrict b = a + n;
  const double* __restrict c = b + n;
  const double s = 3.0;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) a[i] = b[i] + s * c[i];
  }, tbb::static_partitioner());  // STREAM's static schedule: one contiguous block per thread
}

double gather(const Arrays& m, int window) {
  const double* x = m.x();
  const uint32_t* idx = m.idx.get() + window * m.gathers;
  return tbb::parallel_reduce(
      tbb::blocked_range<int64_t>(0, m.gathers), 0.0,
      [&](const tbb::blocked_range<int64_t>& r, double sum) {
        for (int64_t i = r.begin(); i < r.end(); ++i) sum += x[idx[i]];
        return sum;
      },
      [](double l, double r) { return l + r; });
}
// Fresh pages touched per second (one byte per 4 KiB), on 4 KiB pages and on 2 MiB pages
// where the kernel gives them: what a first touch of newly allocated memory costs here (on
// virtual machines a 4 KiB fault can cost tens of microseconds). Best of two passes, each
// on a new mapping of `bytes`.
nlohmann::json first_touch(size_t bytes) {
  nlohmann::json out = nlohmann::json::object();
  for (const bool huge : {false, true}) {
    double best = 0;
    for (int pass = 0; pass < 2; ++pass) {
      void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED) return nullptr;
      madvise(p, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
      volatile char* c = static_cast<char*>(p);
      const auto t0 = Clock::now();
      for (size_t i = 0; i < bytes; i += 4096) c[i] = 1;
      const double s = seconds_since(t0);
      munmap(p, bytes);
      best = pass == 0 ? s : std::min(best, s);
    }
    out[huge ? "huge_pages_bytes_per_second" : "small_pages_bytes_per_second"] = double(bytes) / best;
  }
  out["bytes"] = bytes;
  return out;
}
}  // namespace

size_t last_level_cache_bytes() {
  size_t best = 0;
  int best_level = 0;
  for (int i = 0; i < 16; ++i) {
    const std::string d = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/";
    std::ifstream level_in(d + "level"), type_in(d + "type"), size_in(d + "size");
    int level = 0;
    std::string type, size;
    if (!(level_in >> level) || !(type_in >> type) || !(size_in >> size)) break;
    if (type != "Instruction" && level >= best_level) {
      best = cache_size_bytes(size);
      best_level = level;
    }
  }
  return best;
}

nlohmann::json measure_machine_limits(std::vector<int> thread_counts, const MachineLimitsOptions& opt) {
  const auto t0 = Clock::now();
  const size_t llc = last_level_cache_bytes();
  const size_t footprint = opt.footprint_bytes ? opt.footprint_bytes : std::max<size_t>(4 * llc, size_t(64) << 20);
  const int reps = std::max(1, opt.repetitions);
  Arrays m = make_arrays(footprint, opt.gathers > 0 ? opt.gathers : int64_t(1) << 19);
  const double setup = seconds_since(t0);

  // Each count within the global limit (`--threads`): an arena asks for more, TBB gives less.
  for (int& t : thread_counts) t = std::clamp(t, 1, run_threads());
  std::sort(thread_counts.begin(), thread_counts.end());
  thread_counts.erase(std::unique(thread_counts.begin(), thread_counts.end()), thread_counts.end());
  nlohmann::json triads = nlohmann::json::array(), gathers = nlohmann::json::array();
  // Every gather before any triad: the triad writes a, which is part of x. A window's first
  // sum is its reference; a parallel pass that missed or repeated an element differs (the
  // sums of small integers are exact in any order).
  double window_sum[kWindows];
  int pass = 0;
  for (const int threads : thread_counts) {
    tbb::task_arena arena(threads);
    const Timing g = arena.execute([&] {
      return time_passes(opt.warmup, reps, [&] {
        const int w = pass % kWindows;
        const double s = gather(m, w);
        if (pass < kWindows) window_sum[w] = s;
        else if (s != window_sum[w]) throw std::logic_error("machine limits: a parallel gather missed elements");
        ++pass;
      });
    });
    gathers.push_back({{"threads", threads}, {"gathers_per_second", double(m.gathers) / g.best},
                       {"best_seconds", g.best}, {"median_seconds", g.median}});
  }
  for (const int threads : thread_counts) {
    tbb::task_arena arena(threads);
    const Timing t = arena.execute([&] { return time_passes(opt.warmup, reps, [&] { triad(m); }); });
    const size_t k = m.n_triad / 2;  // the loop covered the array: a spot check
    const double* x = m.x();
    if (x[k] != x[m.n_triad + k] + 3.0 * x[2 * m.n_triad + k])
      throw std::logic_error("machine limits: the triad left an element unwritten");
    const double bytes = 3.0 * sizeof(double) * double(m.n_triad);
    triads.push_back({{"threads", threads}, {"bytes_per_second", bytes / t.best}, {"best_seconds", t.best},
                      {"median_seconds", t.median}});
  }
  return {{"triad", triads},
          {"gather", gathers},
          {"triad_elements", m.n_triad},
          {"triad_bytes_per_pass", 3 * sizeof(double) * m.n_triad},
          {"gather_array_bytes", sizeof(double) * m.n_x},
          {"gathers", m.gathers},
          {"llc_bytes", llc},
          {"huge_pages", m.huge_pages},
          {"repetitions", reps},
          {"warmup", opt.warmup},
          {"setup_seconds", setup},
          {"first_touch", first_touch(size_t(32) << 20)},
          {"seconds", seconds_since(t0)}};
}

bool machine_limits_skipped() {
  const char* v = std::getenv("VOBENCH_MACHINE_LIMITS");
  return v && std::string(v) == "skip";
}

namespace {
nlohmann::json probe_run(Params& params, const ProbeContext& ctx) {
  MachineLimitsOptions opt;
  const int mib = params.get_int("mib", 0, 0, 1 << 16);  // 0: 4 x the last-level cache
  const int gathers_log2 = params.get_int("gathers_log2", 19, 8, 28);
  if (params.dry_run()) return nlohmann::json::object();
  opt.footprint_bytes = size_t(mib) << 20;
  opt.gathers = int64_t(1) << gathers_log2;
  opt.repetitions = ctx.repeats;
  opt.warmup = ctx.warmup;
  nlohmann::json r = measure_machine_limits({1, run_threads()}, opt);
  if (ctx.progress)
    for (size_t i = 0; i < r["triad"].size(); ++i) {
      char line[160];
      std::snprintf(line, sizeof line, "  machine limits, %d thread(s): triad %.3g GB/s, gather %.3g M/s",
                    r["triad"][i]["threads"].get<int>(), r["triad"][i]["bytes_per_second"].get<double>() / 1e9,
                    r["gather"][i]["gathers_per_second"].get<double>() / 1e6);
      ctx.progress(line);
    }
  return r;
}
}  // namespace

ProbeInfo machine_limits_probe_info() {
  return {"machine-limits",
          "STREAM-triad bandwidth and random-gather rate over arrays of 4 x the last-level cache (mib: "
          "another footprint), at 1 thread and the job's thread count; best of the repeats",
          false, probe_run};
}

}  // namespace vob
