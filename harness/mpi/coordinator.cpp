// Rank 0 of the farm: the groups still to do, largest first, to whichever worker is free;
// every record appended to the results file as it arrives (so a farm that is stopped or
// killed resumes like any run); failures to RESULTS.failed.jsonl; progress on stderr.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include "harness/bench/context.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/results.h"
#include "harness/mpi/farm.h"
#include "harness/mpi/farm_messages.h"

namespace vob::farm {

int coordinate(const FarmRequest& req, int ranks, const nlohmann::json& placement) {
  const auto t0 = std::chrono::steady_clock::now();
  if (req.before) req.before();
  // Opened first: it repairs a last line a killed farm left half-written, before it is read.
  ResultsFile results(req.results_path);
  const std::string costs = req.costs_path.empty() ? req.results_path : req.costs_path;
  const KnownRecords known = KnownRecords::read(req.results_path);
  std::vector<JobGroup> groups = plan_groups(req.suites, known, RecordedTimes::read(costs));
  // Each suite's plan line before any job (docs/pipeline.md "Incomplete data").
  for (const FarmSuite& fs : req.suites)
    if (const RunPlan plan = plan_run(fs.suite, fs.tags, known); plan.to_do() > 0)
      results.append(plan_line(new_run_id(), fs.tags.suite_name(fs.suite), fs.tags, plan));
  std::erase_if(groups, [](const JobGroup& g) { return g.done.size() == g.keys.size(); });
  std::stable_sort(groups.begin(), groups.end(),
                   [](const JobGroup& a, const JobGroup& b) { return a.cost_to_do > b.cost_to_do; });
  size_t to_do = 0;
  for (const JobGroup& g : groups) to_do += g.keys.size() - g.done.size();
  std::unique_ptr<ResultsFile> failures;  // opened at the first failure
  std::fprintf(stderr, "%s: MPI farm of %d ranks (rank 0 on %s hands out, %d workers): %zu job groups, %zu jobs to do\n",
               req.name.c_str(), ranks, placement.value("host", "?").c_str(), ranks - 1, groups.size(), to_do);
  std::map<int, std::string> hosts;  // rank -> host, from its context line
  size_t next = 0, written = 0, elsewhere = 0, failed = 0;
  int active = ranks - 1, signal = 0;
  while (active > 0) {
    const auto m = poll(-1);
    if (!m) {
      nap();
      continue;
    }
    if (m->tag == kReady) {
      if (!signal && req.stop_signal) signal = req.stop_signal();
      if (next < groups.size() && !signal) {
        const JobGroup& g = groups[next++];
        send(m->source, kAssign, nlohmann::json{{"suite", g.suite}, {"group", g.id}, {"done", g.done}}.dump());
      } else {
        send(m->source, kStop, "");
        --active;
      }
    } else if (m->tag == kRecord) {
      const nlohmann::json r = nlohmann::json::parse(m->text);
      const bool fresh = results.append(r);
      if (is_context_line(r)) {
        hosts[m->source] = r["context"].value("host_name", "?");
        continue;
      }
      ++(fresh ? written : elsewhere);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "[%zu/%zu %7.1f s] rank %d (%s): %s%s\n", written + elsewhere + failed, to_do, s, m->source,
                   hosts[m->source].c_str(), r.value("key", "").c_str(), fresh ? "" : " (written meanwhile by another run)");
    } else if (m->tag == kFailure) {
      nlohmann::json f = nlohmann::json::parse(m->text);
      const std::string job = f.value("job_key", "");
      f["key"] = "failed|" + f.value("run_id", "") + "|" + (job.empty() ? f.value("group", "") : job);
      if (!failures) failures = std::make_unique<ResultsFile>(failures_path(req.results_path));
      failures->append(f);
      ++failed;
      std::fprintf(stderr, "vobench: %s: rank %d (%s): %s failed: %s\n", req.name.c_str(), m->source,
                   f.value("host", "?").c_str(), job.empty() ? ("group " + f.value("group", "")).c_str() : job.c_str(),
                   f.value("reason", "").c_str());
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::set<std::string> distinct;
  for (const auto& [r, h] : hosts) distinct.insert(h);
  std::fprintf(stderr, "%s: %zu records written, %zu written meanwhile by another run, %zu jobs failed, %zu of %zu groups "
               "handed out, %d workers on %zu hosts, %.1f s -> %s\n",
               req.name.c_str(), written, elsewhere, failed, next, groups.size(), ranks - 1, distinct.size(), s,
               req.results_path.c_str());
  int status = 0;
  if (failed) {
    std::fprintf(stderr, "%s: %zu jobs failed, each with its reason in %s; the others' records are written\n",
                 req.name.c_str(), failed, failures_path(req.results_path).c_str());
    status = 2;
  }
  if (signal) {
    std::fprintf(stderr, "%s: stopped by signal %d; run the same command again to resume\n", req.name.c_str(), signal);
    return 128 + signal;
  }
  return req.after ? req.after(status) : status;
}

}  // namespace vob::farm
