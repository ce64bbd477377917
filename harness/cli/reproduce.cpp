#include "harness/cli/reproduce.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/job_partition.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/resources.h"
#include "harness/bench/results.h"
#include "harness/bench/runner.h"
#include "harness/cli/dry_run.h"
#include "harness/cli/python_script.h"
#include "harness/cli/stop_signals.h"
#include "harness/cli/vtk_render_child.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace fs = std::filesystem;

namespace {
std::string results_of(const std::string& dir) { return (fs::path(dir) / "results.jsonl").string(); }

// One folder, one scale per reproduction: tables never mix tiny and default records.
void check_scale_of_folder(const Reproduction& rep, const std::string& results) {
  std::error_code ec;
  if (!fs::exists(results, ec)) return;
  for (const auto& r : ResultsFile::read_all(results, /*torn_tail_ok=*/true))
    if (r.value("reproduction", "") == rep.name && r.value("scale", "default") != rep.scale)
      throw InputError(results, "records", "hold " + rep.name + "'s records at scale " +
                                               r.value("scale", "default") + ", not " + rep.scale +
                                               ": use --force or another -o folder");
}

// The jobs of a plan in the part (all without one): how many, how many to do, their cost.
struct PartCount {
  size_t jobs = 0, to_do = 0;
  double cost = 0;
};
bool in_part(const RunPart* part, const std::string& suite_name, const PlannedDataset& d, const PlannedJob& j) {
  return !part || !part->take_group || part->take_group(group_id(suite_name, d.label, j.unit));
}
PartCount count_part(const RunPlan& plan, const std::string& suite_name, const RunPart* part) {
  PartCount c;
  for (const PlannedDataset& d : plan.datasets)
    for (const PlannedJob& j : d.jobs)
      if (in_part(part, suite_name, d, j)) {
        ++c.jobs;
        c.to_do += !j.done;
        c.cost += j.done ? 0 : j.cost;
      }
  return c;
}
// --force: the records of these reproductions leave the folder's results file, with the
// images they name and, when one of their suites renders with VTK, the vtk folder. Other
// reproductions' records stay: `reproduce all` writes every paper into one folder, and a
// finished record is only ever dropped by the reproduction that made it.
void drop_records_of(const std::set<std::string>& names, const std::vector<SuiteSpec>& suites,
                     const std::string& out_dir) {
  const std::string results = results_of(out_dir);
  std::error_code ec;
  if (fs::exists(results, ec)) {
    ResultsFile file(results);
    size_t kept = 0;
    const std::vector<nlohmann::json> removed = file.remove_records([&](const nlohmann::json& r) {
      const std::string key = r.value("key", "");
      const size_t slash = key.find('/');
      const bool ours = names.count(r.value("reproduction", "")) > 0 ||
                        (slash != std::string::npos && names.count(key.substr(0, slash)) > 0);
      kept += !ours && !is_plan_line(r);
      return ours;
    });
    for (const nlohmann::json& r : removed) {
      if (!r.contains("images") || !r["images"].is_object()) continue;
      for (const auto& [kind, path] : r["images"].items())
        if (path.is_string() && fs::path(path.get<std::string>()).is_relative())
          fs::remove(fs::path(out_dir) / path.get<std::string>(), ec);
    }
    std::string what;
    for (const std::string& n : names) what += (what.empty() ? "" : ", ") + n;
    const size_t plans = size_t(std::count_if(removed.begin(), removed.end(), is_plan_line));
    std::fprintf(stderr, "--force: %zu records of %s removed from %s (and %zu plan lines); %zu records of others kept\n",
                 removed.size() - plans, what.c_str(), results.c_str(), plans, kept);
  }
  for (const SuiteSpec& suite : suites)
    if (suite.vtk_render) {
      fs::remove_all(fs::path(out_dir) / "vtk", ec);
      if (ec) throw InputError(out_dir, "folder", "cannot be cleared (--force): " + ec.message());
      break;
    }
}
}  // namespace

int run_suites_into(const std::vector<SuiteSpec>& suites, const std::string& name,
                    const std::string& out_dir, bool force, const RunTags& tags, ProgressTracker* all,
                    const RunPart* part) {
  require_writable_folder(out_dir);
  const std::string results = results_of(out_dir);
  if (force) drop_records_of({name}, suites, out_dir);
  const StopSignals signals;
  // [k/N] over every suite of the reproduction, counted before the first scene is made.
  const KnownRecords known = KnownRecords::read(results);
  ProgressTracker tracker(all);
  tracker.set_calibration(known.seconds_per_unit());
  size_t done = 0;
  const std::string revision = source_revision();
  std::map<std::string, size_t> others;  // done jobs of other builds, per revision
  // Every suite's plan line before the first job (docs/pipeline.md "Incomplete data"): a run
  // stopped in its first suite still tells the report what the later ones would have measured.
  std::vector<std::string> run_ids;
  std::optional<ResultsFile> plan_file;
  for (const SuiteSpec& suite : suites) {
    const RunPlan plan = plan_run(suite, tags, known);
    const std::string suite_name = tags.suite_name(suite);
    run_ids.push_back(new_run_id());
    if (plan.to_do() > 0) {
      if (!plan_file) plan_file.emplace(results);
      plan_file->append(plan_line(run_ids.back(), suite_name, tags, plan));
    }
    const PartCount c = count_part(plan, suite_name, part);
    tracker.add(c.jobs, c.cost);
    done += c.jobs - c.to_do;
    for (const auto& [rev, n] : done_by_other_revisions(plan, known, revision,
                                                         [&](const PlannedDataset& d, const PlannedJob& j) {
                                                           return in_part(part, suite_name, d, j);
                                                         }))
      others[rev] += n;
  }
  std::fprintf(stderr, "%s: %zu jobs, %zu already done\n", name.c_str(), tracker.total(), done);
  const std::string note = other_revisions_note(others, revision, "--force");
  if (!note.empty()) std::fprintf(stderr, "%s: %s\n", name.c_str(), note.c_str());
  RunOptions opt;
  opt.results_path = results;
  opt.tags = tags;
  opt.tracker = &tracker;
  opt.known = &known;
  if (part) {
    opt.take_group = part->take_group;
    opt.placement = part->placement;
  }
  opt.stop_requested = [] { return StopSignals::received() != 0; };
  const auto t0 = std::chrono::steady_clock::now();
  opt.progress = [t0](const std::string& line) {
    // Record lines carry their own elapsed time ([k/N] ...); the others get it here.
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (line.rfind("[", 0) == 0)
      std::fprintf(stderr, "%s\n", line.c_str());
    else
      std::fprintf(stderr, "[%6.1f s] %s\n", s, line.c_str());
  };
  opt.write_plan = false;  // written above
  int vtk_failure = 0;  // vobench-vtk's failing status: reported after every suite
  for (size_t si = 0; si < suites.size(); ++si) {
    const SuiteSpec& suite = suites[si];
    std::fprintf(stderr, "suite %s\n", suite.name.c_str());
    opt.run_id = run_ids[si];
    const RunSummary r = run_suite(suite, opt);
    std::cerr << suite.name << ": " << r.written << " records written, " << r.skipped << " kept, ";
    if (r.written_elsewhere) std::cerr << r.written_elsewhere << " written meanwhile by another run, ";
    std::cerr << r.violations << " with oracle violations\n";
    if (r.stopped) {
      const int sig = StopSignals::received();
      std::cerr << name << ": stopped by " << StopSignals::name(sig) << "; every finished record is in "
                << results << ": run the same command again to resume\n";
      return StopSignals::exit_code(sig);
    }
    if (suite.vtk_render && part && part->take_group) {
      std::cerr << name << ": vtk_render is not drawn by a shard: vobench-vtk render --suite after the merge\n";
    } else if (const int v = run_vtk_render(suite, out_dir); v != 0) {
      if (StopSignals::received()) return v;  // stopped in the VTK part: the records are all in
      vtk_failure = v;
    }
  }
  return vtk_failure;
}

int build_tables(const Reproduction& rep, const std::string& out_dir) {
  if (!rep.paper.empty()) return run_python_script("build_tables.py", {out_dir, "--only", rep.name});
  return run_report({results_of(out_dir)}, out_dir, rep.title, rep.name);
}

void prepare_folder(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force) {
  require_writable_folder(out_dir);
  for (const Reproduction& rep : reps)
    if (!force) check_scale_of_folder(rep, results_of(out_dir));
  if (!force) return;
  std::set<std::string> names;
  std::vector<SuiteSpec> suites;
  for (const Reproduction& rep : reps) {
    names.insert(rep.name);
    suites.insert(suites.end(), rep.suites.begin(), rep.suites.end());
  }
  drop_records_of(names, suites, out_dir);
}

int reproduce(const Reproduction& rep, const std::string& out_dir, bool force, ProgressTracker* all,
              const RunPart* part) {
  if (!force) check_scale_of_folder(rep, results_of(out_dir));
  const RunTags tags{rep.name, rep.paper, rep.scale};
  const int status = run_suites_into(rep.suites, rep.name, out_dir, force, tags, all, part);
  if (status != 0 && StopSignals::received()) return status;
  if (part && part->take_group) {
    std::cerr << rep.name << ": a shard's records only; merge the shards (vobench merge) and run vobench report\n";
    return 0;
  }
  const int tables = build_tables(rep, out_dir);
  return status != 0 ? status : tables;  // a failed VTK part still gets its tables
}

int reproduce_all(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force,
                  const RunPart* part) {
  for (const Reproduction& rep : reps)
    if (!force) check_scale_of_folder(rep, results_of(out_dir));
  // [k/N] over every reproduction as well as per reproduction.
  ProgressTracker all;
  {
    const KnownRecords known = force ? KnownRecords() : KnownRecords::read(results_of(out_dir));
    all.set_calibration(known.seconds_per_unit());
    for (const Reproduction& rep : reps)
      for (const SuiteSpec& suite : rep.suites) {
        const RunTags tags{rep.name, rep.paper, rep.scale};
        const PartCount c = count_part(plan_run(suite, tags, known), tags.suite_name(suite), part);
        all.add(c.jobs, c.cost);
      }
    std::cerr << "reproduce all: " << reps.size() << " reproductions, " << all.total() << " jobs\n";
  }
  int first_failure = 0;
  if (force) prepare_folder(reps, out_dir, true);  // every one's records dropped before the first runs
  for (const Reproduction& rep : reps) {
    std::cerr << "reproduce all: " << rep.name << "\n";
    const int status = reproduce(rep, out_dir, false, &all, part);
    if (status == StopSignals::exit_code(SIGINT) || status == StopSignals::exit_code(SIGTERM)) return status;
    if (status != 0) {
      std::cerr << "reproduce all: " << rep.name << " failed (exit " << status << "); going on\n";
      if (first_failure == 0) first_failure = status;
    }
  }
  if (part && part->take_group) return first_failure;
  const int summary = run_python_script("build_tables.py", {out_dir});  // every table and the summary
  return first_failure != 0 ? first_failure : summary;
}

void dry_run_reproductions(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force,
                           const std::string& costs_path) {
  const std::string results = results_of(out_dir);
  const KnownRecords known = force ? KnownRecords() : KnownRecords::read(results);
  const KnownRecords costs = costs_path.empty() ? KnownRecords() : KnownRecords::read(costs_path);
  const KnownRecords* rate = costs_path.empty() ? nullptr : &costs;
  DryRunTotals all;
  for (const Reproduction& rep : reps) {
    DryRunTotals t;
    std::cout << "reproduction " << rep.name << " (" << rep.scale << " scale)\n";
    for (const SuiteSpec& suite : rep.suites) t += print_dry_run(std::cout, suite, RunTags{rep.name, rep.paper, rep.scale}, known);
    print_dry_run_total(std::cout, rep.name, t, known, results, rate, costs_path);
    all += t;
  }
  if (reps.size() > 1) print_dry_run_total(std::cout, "all", all, known, results, rate, costs_path);
}

int report_folder(const std::string& dir, const std::string& suites_dir) {
  const std::string results = results_of(dir);
  std::error_code ec;
  if (!fs::is_regular_file(results, ec)) throw InputError(dir, "folder", "holds no results.jsonl");
  std::set<std::string> generic;  // reproductions without a paper
  bool orderer_records = false;
  for (const auto& r : ResultsFile::read_all(results, /*torn_tail_ok=*/true)) {  // the scripts skip it with a note
    orderer_records = orderer_records || !r.contains("probe");
    if (r.contains("reproduction") && r.value("paper", nlohmann::json()).is_null())
      generic.insert(r["reproduction"].get<std::string>());
  }
  int status = run_python_script("build_tables.py", {dir});
  if (!orderer_records) return status;
  std::string name, title = "vobench report";
  if (generic.size() == 1) {
    name = *generic.begin();
    title = "vobench " + name + " report";
    for (const auto& e : list_reproductions(suites_dir))
      if (e.name == name) title = e.title;
  }
  const int report = run_report({results}, dir, title, name);
  return status != 0 ? status : report;
}

int run_report(const std::vector<std::string>& results, const std::string& out_dir,
               const std::string& title, const std::string& name) {
  std::vector<std::string> args = {"--out", out_dir, "--title", title};
  if (!name.empty()) args.insert(args.end(), {"--name", name});
  args.insert(args.end(), results.begin(), results.end());
  return run_python_script("report.py", args);
}

}  // namespace vob
