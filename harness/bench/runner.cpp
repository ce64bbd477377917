#include "harness/bench/runner.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include <unistd.h>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/external_orderer.h"
#include "harness/bench/job_partition.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/results.h"
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
      throw InputError(describe_overlap(ds.input.empty() ? ds.label() : ds.input, overlaps, &scene.mesh()));
  }
  return scene;
}

// The scene of `ds`, from the caller's cache when it holds it (the cache's old scene is
// dropped first: one scene in memory at a time).
std::shared_ptr<const Scene> cached_scene(const DatasetSpec& ds, const RunOptions& opt) {
  SceneCache* cache = opt.scene_cache;
  if (cache && cache->scene && cache->label == ds.label()) return cache->scene;
  if (cache) cache->scene.reset();
  auto scene = std::make_shared<const Scene>(make_checked_scene(ds, opt.validate_full));
  if (cache) *cache = {ds.label(), scene};
  return scene;
}

// The results file as a sink: the run's context line before its first record.
class FileSink : public RecordSink {
 public:
  FileSink(const std::string& path, nlohmann::json context) : reporter_(path, std::move(context)) {}
  bool done(const std::string& key) override { return reporter_.done(key); }
  bool report(const Record& rec) override { return reporter_.report(rec); }

 private:
  ResultsReporter reporter_;
};
}  // namespace

nlohmann::json lone_placement() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  return {{"host", host}, {"rank", 0}, {"ranks", 1}, {"ranks_on_host", 1}};
}

RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt) {
  namespace fs = std::filesystem;
  RunSummary summary;
  ThreadLimit limit;
  const std::string run_id = opt.run_id.empty() ? new_run_id() : opt.run_id;
  std::optional<FileSink> file_sink;
  if (!opt.sink) file_sink.emplace(opt.results_path, context_line(run_id, opt.context.is_null() ? suite_context(suite) : opt.context));
  RecordSink& results = opt.sink ? *opt.sink : *file_sink;
  const std::string image_dir =
      !opt.image_dir.empty() ? opt.image_dir : (fs::path(opt.results_path).parent_path() / "images").string();
  const ImageReporter images(suite, image_dir, fs::path(opt.results_path).parent_path().string());
  if (images.writes_files() || !suite.probes.empty()) require_writable_folder(image_dir);
  // [k/N] and the time left (progress.h): N counted before the first scene is made. A sink
  // (a farm worker) never reads the file rank 0 is writing.
  const KnownRecords own_known =
      opt.tracker && opt.known ? KnownRecords() : opt.sink ? KnownRecords() : KnownRecords::read(opt.results_path);
  const KnownRecords& known = opt.tracker && opt.known ? *opt.known : own_known;
  const RunPlan planned = plan_run(suite, opt.tags, known);
  const std::string suite_name = opt.tags.suite_name(suite);
  const auto group_of = [&](const std::string& dataset, const std::string& unit) {
    return group_id(suite_name, dataset, unit);
  };
  const auto taken = [&](const std::string& group) { return !opt.take_group || opt.take_group(group); };
  ProgressTracker own_tracker;
  ProgressTracker& tracker = opt.tracker ? *opt.tracker : own_tracker;
  if (!opt.tracker) {
    tracker.set_calibration(known.seconds_per_unit());
    size_t jobs = 0;
    double cost = 0;
    for (const PlannedDataset& d : planned.datasets)
      for (const PlannedJob& j : d.jobs)
        if (taken(group_of(d.label, j.unit))) {
          ++jobs;
          cost += j.done ? 0 : j.cost;
        }
    tracker.add(jobs, cost);
  }
  // The plan line before the jobs (and again on a resume with jobs left): a report can then
  // tell which planned jobs have no record, even of datasets the run never reached.
  if (file_sink && opt.write_plan && planned.to_do() > 0)
    ResultsFile(opt.results_path).append(plan_line(run_id, suite_name, opt.tags, planned));
  const ConsoleReporter console(with_status(opt.progress, tracker));
  Record base = base_record(suite, opt, run_id);
  base.placement = opt.placement.is_null() ? lone_placement() : opt.placement;
  auto stop = [&] { return summary.stopped = opt.stop_requested && opt.stop_requested(); };
  // Writes a finished record, counting it.
  auto report = [&](const Record& rec) {
    const bool written = results.report(rec);
    ++(written ? summary.written : summary.written_elsewhere);
    console.record(rec, written);
  };
  // A failed job: reported and counted when the caller takes failures, else thrown on.
  auto failed = [&](const std::string& key, const std::string& group, const std::exception& e) {
    if (!opt.on_failure) throw;
    opt.on_failure(key, group, e.what());
    ++summary.failed;
  };

  const auto plans = plan_datasets(suite);
  for (size_t di = 0; di < plans.size(); ++di) {
    const DatasetPlan& plan = plans[di];
    const std::string label = plan.dataset.label();
    const PlannedDataset& pd = planned.datasets[di];
    if (opt.take_group &&
        std::none_of(pd.jobs.begin(), pd.jobs.end(), [&](const PlannedJob& j) { return taken(group_of(label, j.unit)); }))
      continue;
    if (stop()) return summary;
    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const Scene> made;
    try {
      made = cached_scene(plan.dataset, opt);
    } catch (const std::exception& e) {
      if (!opt.on_failure) throw;
      for (const PlannedJob& j : pd.jobs)
        if (taken(group_of(label, j.unit)) && !results.done(j.key)) {
          failed(j.key, group_of(label, j.unit), e);
          tracker.skipped(j.done ? 0 : j.cost);
        }
      continue;
    }
    const Scene& scene = *made;
    console.dataset(di, plans.size(), label, scene, seconds_since(t0));
    Record dataset_base = base;
    dataset_base.dataset = label;
    dataset_base.row = plan.dataset.row_label();
    dataset_base.dataset_spec = plan.dataset.to_json();
    dataset_base.facts = scene_facts(scene);
    std::vector<Job> jobs = dataset_jobs(suite, plan, scene, opt.tags);
    std::erase_if(jobs, [&](const Job& j) { return !taken(group_of(label, job_unit(j))); });
    const double primitives = double(scene.num_primitives());
    const PlannedDataset now = plan_made(suite, label, jobs, primitives, known);
    double old_cost = 0;
    size_t old_jobs = 0;
    for (const PlannedJob& j : pd.jobs)
      if (taken(group_of(label, j.unit))) {
        ++old_jobs;
        old_cost += j.done ? 0 : j.cost;
      }
    tracker.replace(old_jobs, old_cost, now.jobs.size(), now.cost_to_do());
    // A finished measurement: its images, its record, the run's counts.
    auto finished = [&](const Job& job, Measurement& m, double seconds) {
      if (m.violated) ++summary.violations;
      images.report(m, scene, job.camera);
      m.record.job_seconds = seconds;
      tracker.finished(job_cost(suite, job, primitives));
      report(m.record);
    };
    auto probe = [&](const Job& job, const Record& job_base, std::chrono::steady_clock::time_point job_start) {
      Record rec = run_probe_job(job, &scene, suite, &plan.dataset, job_base, image_dir, opt.progress);
      rec.job_seconds = seconds_since(job_start);
      tracker.finished(job_cost(suite, job, primitives));
      report(rec);
    };
    // "interleave": each set of jobs that differ only in their orderer (one view, size and
    // thread count) measured in turns, a frame of each orderer at a time, warm-up frames
    // first; every orderer of the dataset is prepared once and kept until the dataset ends.
    // False when a stop was asked for: checked between sets, as a plain run checks between
    // jobs, so the set in progress is finished and written first.
    auto run_interleaved = [&]() -> bool {
      std::map<std::string, std::unique_ptr<PreparedOrderer>> ready;  // by spec and threads
      std::vector<std::string> set_order;
      std::map<std::string, std::vector<const Job*>> sets;
      for (const Job& job : jobs) {
        const std::string k = std::to_string(job.threads) + "|" + std::to_string(job.w) + "x" + std::to_string(job.h) +
                              "|" + std::to_string(job.view_index);
        if (!sets.count(k)) set_order.push_back(k);
        sets[k].push_back(&job);
      }
      struct Turn {
        const Job* job;
        std::string slot;          // its key in `ready`
        PreparedOrderer* p;        // null once it failed
        FrameMeasurement frames;
        double seconds = 0;        // its own prepare, frames and verdict
      };
      for (const std::string& k : set_order) {
        if (stop()) return false;
        std::vector<Turn> turns;
        for (const Job* job : sets[k]) {
          if (results.done(job->key)) {
            ++summary.skipped;
            tracker.skipped(known.keys.count(job->key) ? 0 : job_cost(suite, *job, primitives));
            continue;
          }
          limit.set(job->threads);
          Record job_base = dataset_base;
          job_base.threads = run_threads();
          const auto t0 = std::chrono::steady_clock::now();
          const std::string slot = job->spec + "|" + std::to_string(job->threads);
          try {
            if (job->kind == Job::Kind::Probe) {
              probe(*job, job_base, t0);
              continue;
            }
            std::unique_ptr<PreparedOrderer>& p = ready[slot];
            if (!p) p = std::make_unique<PreparedOrderer>(prepare_orderer(job->spec, scene));
            set_external_view_index(*p->orderer, job->view_index);
            turns.push_back({job, slot, p.get(), {}, seconds_since(t0)});
          } catch (const std::exception& e) {
            ready.erase(slot);
            failed(job->key, group_of(label, job_unit(*job)), e);
            tracker.finished(job_cost(suite, *job, primitives));
          }
        }
        const auto fail = [&](Turn& t, const std::exception& e) {
          ready.erase(t.slot);  // an orderer that threw is not trusted with the next view
          t.p = nullptr;
          failed(t.job->key, group_of(label, job_unit(*t.job)), e);
          tracker.finished(job_cost(suite, *t.job, primitives));
        };
        // As measure_frame: a turn's output, warm-up frames' too, is kept until its next frame
        // and freed first, so the turns' outputs alive at once are the same from the first
        // warm-up round on and no timed frame faults in a new one.
        const auto frame = [&](Turn& t, bool timed) {
          if (!t.p) return;
          const auto t0 = std::chrono::steady_clock::now();
          try {
            t.frames.ordering = Ordering{};
            PhaseClock clock;
            t.frames.ordering = t.p->orderer->order(t.job->camera, clock);
            if (timed) t.frames.repeats.push_back(clock.phases());
          } catch (const std::exception& e) {
            fail(t, e);
          }
          t.seconds += seconds_since(t0);
        };
        for (int w = 0; w < suite.warmup; ++w)
          for (Turn& t : turns) frame(t, false);
        for (int r = 0; r < suite.repeats; ++r)
          for (Turn& t : turns) frame(t, true);
        for (Turn& t : turns) {
          if (!t.p) continue;
          const auto t0 = std::chrono::steady_clock::now();
          try {
            Record job_base = dataset_base;
            job_base.threads = run_threads();
            Measurement m = finish_orderer_job(*t.job, *t.p, scene, suite, job_base, std::move(t.frames));
            finished(*t.job, m, t.seconds + seconds_since(t0));
          } catch (const std::exception& e) {
            fail(t, e);
          }
        }
      }
      return true;
    };
    if (suite.interleave) {
      if (!run_interleaved()) return summary;
      continue;
    }
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
      const auto job_start = std::chrono::steady_clock::now();
      try {
        if (job.kind == Job::Kind::Probe) {
          probe(job, job_base, job_start);
          continue;
        }
        // Prepared again per thread count: prepare is timed too, and may run in parallel.
        if (!prepared || prepared->spec != job.spec || prepared_threads != job.threads) {
          prepared.reset();  // the previous orderer's memory goes first
          prepared = std::make_unique<PreparedOrderer>(prepare_orderer(job.spec, scene));
          prepared_threads = job.threads;
        }
        Measurement m = measure_orderer_job(job, *prepared, scene, suite, job_base);
        finished(job, m, seconds_since(job_start));
      } catch (const std::exception& e) {
        prepared.reset();  // an orderer that threw is not trusted with the next view
        failed(job.key, group_of(label, job_unit(job)), e);
        tracker.finished(job_cost(suite, job, primitives));
      }
    }
  }
  for (const ProbeSpec* probe : sceneless_probes(suite))
    for (const Job& job : sceneless_jobs(suite, *probe, opt.tags)) {
      if (!taken(group_of("", job_unit(job)))) continue;
      if (stop()) return summary;
      if (results.done(job.key)) {
        ++summary.skipped;
        tracker.skipped(known.keys.count(job.key) ? 0 : job_cost(suite, job, 0));
        continue;
      }
      limit.set(job.threads);
      Record job_base = base;
      job_base.threads = run_threads();
      const auto job_start = std::chrono::steady_clock::now();
      try {
        Record rec = run_probe_job(job, nullptr, suite, nullptr, job_base, image_dir, opt.progress);
        rec.job_seconds = seconds_since(job_start);
        tracker.finished(job_cost(suite, job, 0));
        report(rec);
      } catch (const std::exception& e) {
        failed(job.key, group_of("", job_unit(job)), e);
        tracker.finished(job_cost(suite, job, 0));
      }
    }
  return summary;
}

}  // namespace vob
