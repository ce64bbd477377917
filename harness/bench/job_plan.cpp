#include "harness/bench/job_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include "datasets/datasets.h"
#include "harness/bench/context.h"
#include "harness/bench/record.h"
#include "harness/bench/results.h"

namespace vob {

namespace {
constexpr double kUnknownPrimitives = 1e5;

double param(const DatasetSpec& ds, const std::string& key, double def) {
  const auto it = ds.set.find(key);
  if (it == ds.set.end()) return def;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  return end && *end == '\0' && std::isfinite(v) ? v : def;
}

// The kind of an input file from its extension (what load_input dispatches on).
SceneKind input_kind(const DatasetSpec& ds) {
  std::string ext = std::filesystem::path(ds.input).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".gz") ext = std::filesystem::path(ds.input).stem().extension().string() + ext;
  if (ext == ".vti" || ext == ".inr" || ext == ".inr.gz") return SceneKind::Voxels;
  if ((ext == ".off" || ext == ".stl" || ext == ".ply" || ext == ".obj") && !ds.tetrahedralize)
    return SceneKind::Triangles;
  return SceneKind::Cells;
}


// A scene of `kind` small enough to make in microseconds: it stands in for the dataset when
// its jobs are listed (keys, views; the cameras of datasets with their own depend only on
// the bounding box, their number not at all).
const Scene& stand_in(SceneKind kind) {
  static const Scene cells = [] {
    Params p("gap");
    for (const char* k : {"nx", "ny", "nz"}) p.set(k, "1");
    return make_dataset("gap", p);
  }();
  static const Scene triangles = [] {
    Params p("sphere");
    p.set("subdiv", "0");
    return make_dataset("sphere", p);
  }();
  static const Scene voxels = [] {
    Params p("shells");
    for (const char* k : {"nx", "ny", "nz"}) p.set(k, "8");
    return make_dataset("shells", p);
  }();
  return kind == SceneKind::Cells ? cells : kind == SceneKind::Triangles ? triangles : voxels;
}

std::string job_line(const Job& j) {
  if (j.kind == Job::Kind::Probe) return j.probe->label();
  return j.spec + " view " + std::to_string(j.view_index) + " " + std::to_string(j.w) + "x" + std::to_string(j.h);
}
}  // namespace

std::string job_unit(const Job& job) { return job.kind == Job::Kind::Probe ? job.probe->label() : job.spec; }

SceneKind dataset_kind(const DatasetSpec& ds) {
  return ds.input.empty() ? find_dataset(ds.name).kind : input_kind(ds);
}

double orderer_job_cost(double primitives, double pixels, int repeats, int warmup, int oracle_samples) {
  return (repeats + warmup) * primitives + pixels * std::max(1, oracle_samples) + (oracle_samples > 0 ? primitives : 0);
}

double probe_job_cost(double primitives, int repeats, int warmup) {
  return (repeats + warmup) * (primitives > 0 ? primitives : kUnknownPrimitives);
}

double job_cost(const SuiteSpec& suite, const Job& job, double primitives) {
  if (job.kind == Job::Kind::Probe) return probe_job_cost(primitives, job.probe->repeats, job.probe->warmup);
  return orderer_job_cost(primitives, double(job.w) * job.h, suite.repeats, suite.warmup,
                          suite.oracle ? suite.supersample * suite.supersample : 0);
}

double estimated_primitives(const DatasetSpec& ds, std::string* from) {
  if (from) *from = "parameters";
  if (!ds.input.empty()) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(ds.input, ec);
    if (from) *from = "file size (a guess)";
    return ec ? 0 : double(bytes) / 60;  // ~60 bytes per cell in VTK/TetGen text or XML
  }
  const std::string& n = ds.name;
  const auto p = [&](const char* k, double d) { return param(ds, k, d); };
  if (n == "gap") return 6 * p("nx", 50) * p("ny", 50) * p("nz", 100);
  if (n == "helix") return p("cells", 20000);
  if (n == "zoo") return 7200 * std::pow(p("scale", 1), 3);
  if (n == "sphere") return 20 * std::pow(4, p("subdiv", 3));
  if (n == "spheres") return 180 * std::pow(4, p("subdiv", 2));
  if (n == "block" || n == "shells" || n == "sparse") return p("nx", 64) * p("ny", 64) * p("nz", 64);
  if (n == "skull") return 64 * 64 * 64;
  if (n == "edge-on") return 6 * std::pow(p("n", 8), 3);
  if (n == "eye-in-plane" || n == "eye-inside") return 6 * std::pow(p("n", 6), 3);
  if (n.rfind("touching-", 0) == 0) return 6 * std::pow(p("n", 6), 3);
  if (n == "slivers") return 6 * std::pow(p("n", 8), 2) * 3;
  if (n == "tiny") return p("count", 2000);
  if (n == "cycle") return p("cells", 6);
  if (n == "cycle-sticks") return 3;
  if (n == "offset") return 20000;
  if (from) *from = "unknown (1e5 assumed)";
  return 0;
}

KnownRecords KnownRecords::read(const std::string& results_path) {
  KnownRecords k;
  std::error_code ec;
  if (results_path.empty() || !std::filesystem::is_regular_file(results_path, ec)) return k;
  const std::vector<nlohmann::json> lines = ResultsFile::read_all_lines(results_path, /*torn_tail_ok=*/true);
  std::map<std::string, std::string> run_revision;  // run_id -> its context's git_sha
  for (const auto& r : lines)
    if (r.is_object() && is_context_line(r) && r.contains("run_id") && r["run_id"].is_string() &&
        r["context"].is_object() && r["context"].contains("git_sha") && r["context"]["git_sha"].is_string())
      run_revision.emplace(r["run_id"].get<std::string>(), r["context"]["git_sha"].get<std::string>());
  for (const auto& r : lines) {
    if (!r.is_object() || is_meta_line(r)) continue;
    if (r.contains("key") && r["key"].is_string()) {
      k.keys.insert(r["key"].get<std::string>());
      if (r.contains("run_id") && r["run_id"].is_string()) {
        const auto it = run_revision.find(r["run_id"].get<std::string>());
        k.revision.emplace(r["key"].get<std::string>(), it == run_revision.end() ? "" : it->second);
      }
    }
    if (!r.contains("dataset") || !r["dataset"].is_string() || !r.contains("n") || !r["n"].is_number()) continue;
    const double n = r["n"].get<double>();
    k.primitives[r["dataset"].get<std::string>()] = n;
    // Calibration: an orderer record's frames (repeats + warmup at its median). The oracle,
    // images and scene are not in the record, so this rate is a lower bound.
    const auto total = r.value("total", nlohmann::json());
    if (r.contains("probe") || !total.is_object() || !total.contains("median") || !total["median"].is_number())
      continue;
    const int frames = r.value("repeats", 0) + r.value("warmup", 0);
    const double pixels = r.value("pixels", 0.0);
    if (frames <= 0 || pixels <= 0) continue;
    k.seconds += frames * total["median"].get<double>();
    k.cost += orderer_job_cost(n, 0, r.value("repeats", 0), r.value("warmup", 0), 0);  // frames only
    ++k.timed;
  }
  return k;
}

size_t PlannedDataset::to_do() const {
  size_t n = 0;
  for (const auto& j : jobs) n += !j.done;
  return n;
}

double PlannedDataset::cost_to_do() const {
  double c = 0;
  for (const auto& j : jobs)
    if (!j.done) c += j.cost;
  return c;
}

size_t RunPlan::jobs() const {
  size_t n = 0;
  for (const auto& d : datasets) n += d.jobs.size();
  return n;
}

size_t RunPlan::to_do() const {
  size_t n = 0;
  for (const auto& d : datasets) n += d.to_do();
  return n;
}

double RunPlan::cost_to_do() const {
  double c = 0;
  for (const auto& d : datasets) c += d.cost_to_do();
  return c;
}

namespace {
PlannedJob planned(const SuiteSpec& suite, const Job& j, double primitives, const KnownRecords& known) {
  PlannedJob pj;
  pj.key = j.key;
  pj.line = job_line(j);
  pj.unit = job_unit(j);
  pj.probe = j.kind == Job::Kind::Probe;
  pj.pixels = pj.probe ? 0 : double(j.w) * j.h;
  pj.done = known.keys.count(j.key) > 0;
  pj.cost = job_cost(suite, j, primitives);
  if (pj.probe) {
    pj.probe_label = j.probe->name;  // what its record says in "probe"
  } else {
    pj.algorithm = j.spec;
    pj.w = j.w;
    pj.h = j.h;
    pj.view_index = j.view_index;
  }
  pj.threads = effective_threads(j.threads);
  return pj;
}
}  // namespace

PlannedDataset plan_made(const SuiteSpec& suite, const std::string& label, const std::vector<Job>& jobs,
                         double primitives, const KnownRecords& known) {
  PlannedDataset pd;
  pd.label = label;
  pd.primitives = primitives;
  pd.size_from = "scene";
  for (const Job& j : jobs) pd.jobs.push_back(planned(suite, j, primitives, known));
  return pd;
}

RunPlan plan_run(const SuiteSpec& suite, const RunTags& tags, const KnownRecords& known) {
  RunPlan plan;
  const auto add = [&](PlannedDataset& pd, const Job& j) { pd.jobs.push_back(planned(suite, j, pd.primitives, known)); };
  for (const DatasetPlan& dp : plan_datasets(suite)) {
    PlannedDataset pd;
    pd.label = dp.dataset.label();
    pd.row = dp.dataset.row_label();
    pd.dataset_spec = dp.dataset.to_json();
    pd.kind = dataset_kind(dp.dataset);
    const auto it = known.primitives.find(pd.label);
    if (it != known.primitives.end()) {
      pd.primitives = it->second;
      pd.size_from = "records";
    } else {
      pd.primitives = estimated_primitives(dp.dataset, &pd.size_from);
    }
    if (!dp.dataset.input.empty()) pd.views_note = "kind from the file extension";
    if (dp.dataset.input.empty() && find_dataset(dp.dataset.name).views && suite.view_directions.empty() &&
        !suite.orbit)
      pd.views_note = "views: the dataset's own cameras";
    for (const Job& j : dataset_jobs(suite, dp, stand_in(pd.kind), tags)) add(pd, j);
    plan.datasets.push_back(std::move(pd));
  }
  PlannedDataset sceneless;
  for (const ProbeSpec* p : sceneless_probes(suite))
    for (const Job& j : sceneless_jobs(suite, *p, tags)) add(sceneless, j);
  if (!sceneless.jobs.empty()) plan.datasets.push_back(std::move(sceneless));
  return plan;
}

nlohmann::json plan_line(const std::string& run_id, const std::string& suite_name, const RunTags& tags,
                         const RunPlan& plan) {
  nlohmann::json jobs = nlohmann::json::array();
  for (const PlannedDataset& d : plan.datasets)
    for (const PlannedJob& j : d.jobs) {
      nlohmann::json o = {{"key", j.key},
                          {"dataset", d.label.empty() ? nlohmann::json() : nlohmann::json(d.label)},
                          {"dataset_spec", d.dataset_spec}};
      if (!d.row.empty()) o["row"] = d.row;
      if (j.probe) {
        o["probe"] = j.probe_label;
      } else {
        o["algorithm"] = j.algorithm;
        o["w"] = j.w;
        o["h"] = j.h;
        o["view_index"] = j.view_index;
      }
      o["threads"] = j.threads;
      jobs.push_back(std::move(o));
    }
  nlohmann::json line = {{"key", "plan|" + run_id + "|" + suite_name},
                         {"type", "plan"},
                         {"run_id", run_id},
                         {"schema_version", kSchemaVersion},
                         {"suite", suite_name}};
  if (!tags.reproduction.empty()) line["reproduction"] = tags.reproduction;
  line["scale"] = tags.scale;
  line["jobs"] = std::move(jobs);
  return line;
}

bool is_plan_line(const nlohmann::json& j) { return j.is_object() && j.contains("type") && j["type"] == "plan"; }

bool is_meta_line(const nlohmann::json& j) { return is_context_line(j) || is_plan_line(j); }

std::map<std::string, size_t> done_by_other_revisions(const RunPlan& plan, const KnownRecords& known,
                                                      const std::string& current, const PlannedJobFilter& take) {
  std::map<std::string, size_t> others;
  for (const PlannedDataset& d : plan.datasets)
    for (const PlannedJob& j : d.jobs) {
      if (!j.done || (take && !take(d, j))) continue;
      const auto it = known.revision.find(j.key);
      const std::string rev = it == known.revision.end() ? "" : it->second;
      if (rev != current) ++others[rev.empty() ? "unknown" : rev];
    }
  return others;
}

std::string other_revisions_note(const std::map<std::string, size_t>& others, const std::string& current,
                                 const std::string& to_measure_again) {
  if (others.empty()) return "";
  size_t n = 0;
  std::string revs;
  for (const auto& [rev, count] : others) {
    n += count;
    revs += (revs.empty() ? "" : ", ") + std::to_string(count) + " by " + rev;
  }
  return std::to_string(n) + " of the jobs done were measured by other builds (" + revs + "), not by this one (" +
         (current.empty() ? "unknown" : current) + "): they are kept, and reported under their revision; " +
         to_measure_again + " measures them again";
}

}  // namespace vob
