#include "harness/bench/job_partition.h"

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "harness/bench/results.h"

namespace vob {

namespace {
double number(const nlohmann::json& r, const char* k) {
  return r.contains(k) && r[k].is_number() ? r[k].get<double>() : 0;
}

// The cost units of a recorded job, as job_cost would charge it.
double record_units(const nlohmann::json& r) {
  const double n = number(r, "n");
  const int repeats = int(number(r, "repeats")), warmup = int(number(r, "warmup"));
  if (r.contains("probe")) return probe_job_cost(n, repeats, warmup);
  int samples = 0;
  if (r.contains("oracle") && r["oracle"].is_object()) {
    const int s = std::max(1, int(number(r["oracle"], "supersample")));
    samples = s * s;
  }
  return orderer_job_cost(n, number(r, "pixels"), repeats, warmup, samples);
}

// The job's seconds: the wall time the runner recorded, else (older records) its frames.
double record_seconds(const nlohmann::json& r) {
  if (number(r, "job_seconds") > 0) return number(r, "job_seconds");
  if (r.contains("probe")) return number(r, "seconds");
  const auto total = r.value("total", nlohmann::json());
  if (!total.is_object()) return 0;
  return (number(r, "repeats") + number(r, "warmup")) * number(total, "median");
}
}  // namespace

RecordedTimes RecordedTimes::read(const std::string& path) {
  RecordedTimes t;
  std::error_code ec;
  if (path.empty() || !std::filesystem::is_regular_file(path, ec)) return t;
  for (const auto& r : ResultsFile::read_all(path, /*torn_tail_ok=*/true)) {
    if (!r.is_object() || !r.contains("key") || !r["key"].is_string()) continue;
    const double s = record_seconds(r), u = record_units(r);
    if (!(s > 0)) continue;
    t.job_seconds[r["key"].get<std::string>()] = s;
    if (u > 0) {
      t.seconds += s;
      t.units += u;
    }
    ++t.records;
    const auto prep = r.value("prepare", nlohmann::json());
    if (prep.is_object() && r.contains("dataset") && r["dataset"].is_string() && r.contains("algorithm"))
      t.prepare_seconds[r["dataset"].get<std::string>() + "|" + r.value("algorithm", "")] = number(prep, "seconds");
  }
  return t;
}

std::string group_id(const std::string& suite, const std::string& dataset, const std::string& unit) {
  return suite + " / " + (dataset.empty() ? "(no scene)" : dataset) + " / " + unit;
}

void add_groups(std::vector<JobGroup>& out, size_t suite_index, const std::string& suite_name,
                const RunPlan& plan, const RecordedTimes& times) {
  const double rate = times.seconds_per_unit();
  for (const PlannedDataset& d : plan.datasets) {
    const size_t first = out.size();
    for (const PlannedJob& j : d.jobs) {
      const std::string id = group_id(suite_name, d.label, j.unit);
      auto it = std::find_if(out.begin() + long(first), out.end(), [&](const JobGroup& g) { return g.id == id; });
      if (it == out.end()) {
        JobGroup g;
        g.id = id;
        g.suite = suite_index;
        g.dataset = d.label;
        g.unit = j.unit;
        out.push_back(std::move(g));
        it = out.end() - 1;
      }
      const auto rec = times.job_seconds.find(j.key);
      const double c = rate > 0 ? (rec != times.job_seconds.end() ? rec->second : j.cost * rate) : j.cost;
      it->keys.push_back(j.key);
      it->cost += c;
      if (j.done)
        it->done.push_back(j.key);
      else
        it->cost_to_do += c;
    }
    // The orderer's recorded prepare, once per group (and only if the group has work left).
    for (auto g = out.begin() + long(first); g != out.end() && rate > 0; ++g) {
      const auto prep = times.prepare_seconds.find(g->dataset + "|" + g->unit);
      if (prep == times.prepare_seconds.end()) continue;
      g->cost += prep->second;
      if (g->done.size() < g->keys.size()) g->cost_to_do += prep->second;
    }
  }
}

Schedule list_schedule(const std::vector<double>& costs, int parts) {
  Schedule s;
  s.part.assign(costs.size(), 0);
  s.loads.assign(size_t(std::max(parts, 1)), 0.0);
  std::vector<size_t> order(costs.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costs[a] > costs[b]; });
  for (size_t i : order) {
    const auto least = std::min_element(s.loads.begin(), s.loads.end());  // first of equals
    *least += costs[i];
    s.part[i] = int(least - s.loads.begin());
    s.total += costs[i];
  }
  if (!order.empty()) s.largest = int(order.front());
  s.makespan = s.loads.empty() ? 0 : *std::max_element(s.loads.begin(), s.loads.end());
  return s;
}

std::vector<const JobGroup*> shard_groups(const std::vector<JobGroup>& groups, int index, int count) {
  std::vector<double> costs;
  for (const JobGroup& g : groups) costs.push_back(g.cost);
  const Schedule s = list_schedule(costs, count);
  std::vector<const JobGroup*> mine;
  for (size_t i = 0; i < groups.size(); ++i)
    if (s.part[i] == index - 1) mine.push_back(&groups[i]);
  return mine;
}

}  // namespace vob
