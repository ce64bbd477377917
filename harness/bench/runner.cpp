#include "harness/bench/runner.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/reporters.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What every record of the run shares; the dataset's part is added per dataset.
Record base_record(const SuiteSpec& suite, const RunOptions& opt, const std::string& run_id) {
  Record r;
  r.suite = opt.tags.suite_name(suite);
  r.repeats = suite.repeats;
  r.warmup = suite.warmup;
  r.threads = run_threads();  // each job's record sets its own (with_threads)
  r.reproduction = opt.tags.reproduction;
  r.paper = opt.tags.paper;
  r.scale = opt.tags.scale;
  r.run_id = run_id;
  return r;
}

// The run's TBB limit, changed only when a job's thread count differs from the last one's.
class ThreadLimit {
 public:
  void set(int threads) {
    if (threads == current_) return;
    control_.reset();
    if (threads > 0) control_.emplace(tbb::global_control::max_allowed_parallelism, threads);
    current_ = threads;
  }

 private:
  std::optional<tbb::global_control> control_;
  int current_ = 0;
};

// The run's context: the parallelism of every thread count of the suite.
nlohmann::json suite_context(const SuiteSpec& suite) {
  nlohmann::json counts = nlohmann::json::array();
  for (int t : suite.threads) counts.push_back(effective_threads(t));
  nlohmann::json c = run_context(counts[0].get<int>());
  if (counts.size() > 1) c["thread_counts"] = counts;
  return c;
}

Scene make_checked_scene(const DatasetSpec& ds, bool validate_full) {
  Scene scene = make_scene(ds);
  if (validate_full && scene.kind() == SceneKind::Cells) {
    const CellOverlapReport overlaps = check_overlapping_cells(scene.mesh(), scene.faces());
    if (!overlaps.pairs.empty())
      throw InputError(describe_overlap(ds.input.empty() ? ds.label() : ds.input, overlaps));
  }
  return scene;
}
}  // namespace

RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt) {
  namespace fs = std::filesystem;
  RunSummary summary;
  ThreadLimit limit;
  const std::string run_id = new_run_id();
  ResultsReporter results(opt.results_path, context_line(run_id, suite_context(suite)));
  const std::string image_dir =
      !opt.image_dir.empty() ? opt.image_dir : (fs::path(opt.results_path).parent_path() / "images").string();
  const ImageReporter images(suite, image_dir, fs::path(opt.results_path).parent_path().string());
  if (images.writes_files() || !suite.probes.empty()) require_writable_folder(image_dir);
  // [k/N] and the time left (progress.h): N counted before the first scene is made.
  const KnownRecords own_known = opt.tracker && opt.known ? KnownRecords() : KnownRecords::read(opt.results_path);
  const KnownRecords& known = opt.tracker && opt.known ? *opt.known : own_known;
  const RunPlan planned = plan_run(suite, opt.tags, known);
  ProgressTracker own_tracker;
  ProgressTracker& tracker = opt.tracker ? *opt.tracker : own_tracker;
  if (!opt.tracker) {
    tracker.set_calibration(known.seconds_per_unit());
    tracker.add(planned.jobs(), planned.cost_to_do());
  }
  const ConsoleReporter console(with_status(opt.progress, tracker));
  const Record base = base_record(suite, opt, run_id);
  auto stop = [&] { return summary.stopped = opt.stop_requested && opt.stop_requested(); };
  // Writes a finished record, counting it.
  auto report = [&](const Record& rec) {
    const bool written = results.report(rec);
    ++(written ? summary.written : summary.written_elsewhere);
    console.record(rec, written);
  };

  const auto plans = plan_datasets(suite);
  for (size_t di = 0; di < plans.size(); ++di) {
    const DatasetPlan& plan = plans[di];
    if (stop()) return summary;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene scene = make_checked_scene(plan.dataset, opt.validate_full);
    console.dataset(di, plans.size(), plan.dataset.label(), scene, seconds_since(t0));
    Record dataset_base = base;
    dataset_base.dataset = plan.dataset.label();
    dataset_base.row = plan.dataset.row_label();
    dataset_base.dataset_spec = plan.dataset.to_json();
    dataset_base.facts = scene_facts(scene);
    const std::vector<Job> jobs = dataset_jobs(suite, plan, scene, opt.tags);
    const double primitives = double(scene.num_primitives());
    const PlannedDataset made = plan_made(suite, plan.dataset.label(), jobs, primitives, known);
    tracker.replace(planned.datasets[di].jobs.size(), planned.datasets[di].cost_to_do(), made.jobs.size(),
                    made.cost_to_do());
    std::unique_ptr<PreparedOrderer> prepared;  // of the current spec, once a record is missing
    int prepared_threads = -1;                  // the thread count it was prepared under
    for (const Job& job : jobs) {
      if (stop()) return summary;
      if (results.done(job.key)) {
        ++summary.skipped;
        tracker.skipped(known.keys.count(job.key) ? 0 : job_cost(suite, job, primitives));
        continue;
      }
      limit.set(job.threads);
      Record job_base = dataset_base;
      job_base.threads = run_threads();
      if (job.kind == Job::Kind::Probe) {
        Record rec = run_probe_job(job, &scene, suite, &plan.dataset, job_base, image_dir, opt.progress);
        tracker.finished(job_cost(suite, job, primitives));
        report(rec);
        continue;
      }
      // Prepared again per thread count: prepare is timed too, and may run in parallel.
      if (!prepared || prepared->spec != job.spec || prepared_threads != job.threads) {
        prepared.reset();  // the previous orderer's memory goes first
        prepared = std::make_unique<PreparedOrderer>(prepare_orderer(job.spec, scene));
        prepared_threads = job.threads;
      }
      Measurement m = measure_orderer_job(job, *prepared, scene, suite, job_base);
      if (m.violated) ++summary.violations;
      images.report(m, scene, job.camera);
      tracker.finished(job_cost(suite, job, primitives));
      report(m.record);
    }
  }
  for (const ProbeSpec* probe : sceneless_probes(suite))
    for (const Job& job : sceneless_jobs(suite, *probe, opt.tags)) {
      if (stop()) return summary;
      if (results.done(job.key)) {
        ++summary.skipped;
        tracker.skipped(known.keys.count(job.key) ? 0 : job_cost(suite, job, 0));
        continue;
      }
      limit.set(job.threads);
      Record job_base = base;
      job_base.threads = run_threads();
      Record rec = run_probe_job(job, nullptr, suite, nullptr, job_base, image_dir, opt.progress);
      tracker.finished(job_cost(suite, job, 0));
      report(rec);
    }
  return summary;
}

}  // namespace vob
