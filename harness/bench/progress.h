// `[k/N] 00:41 elapsed, ~03:10 left` for run and reproduce (docs/pipeline.md "Progress and
// --dry-run"). N is counted before the first scene is made (job_plan.h) and corrected when a
// scene is made (a dataset's real size and views); k counts finished and skipped jobs. The
// time left is the cost of the jobs still to do (job_plan.h's model) times the seconds per
// cost unit measured on this run's computed jobs (skipped ones are not in the rate); before
// the first job finishes it uses a calibration from earlier records, if any.
#pragma once
#include <chrono>
#include <functional>
#include <string>

namespace vob {

class ProgressTracker {
 public:
  // `parent`: an outer tracker (reproduce all) that counts its own plan (add is not passed
  // on) and to which every correction, skip and finished job is passed on; its count and
  // time left are shown after this one's.
  explicit ProgressTracker(ProgressTracker* parent = nullptr);
  void set_calibration(double seconds_per_unit) { prior_rate_ = seconds_per_unit; }

  // Planned jobs: `jobs` in all; those still to be computed cost `cost_to_do`.
  void add(size_t jobs, double cost_to_do);
  // A dataset's planned numbers replaced by the real ones once its scene is made.
  void replace(size_t old_jobs, double old_cost, size_t jobs, double cost);
  // A job found done; `cost`: its cost when the plan counted it as to do (another run
  // wrote it meanwhile), else 0.
  void skipped(double cost = 0);
  void finished(double cost);         // a computed job
  // "[k/N] MM:SS elapsed, ~MM:SS left" (and " (all: [k/N], ~H:MM:SS left)" with a parent).
  std::string status() const;
  size_t done() const { return done_; }
  size_t total() const { return jobs_; }

  static std::string clock_text(double seconds);  // "00:41", "03:10", "1:02:03"

 private:
  std::string count_text() const;
  double seconds_left() const;  // < 0: unknown
  ProgressTracker* parent_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  size_t jobs_ = 0, done_ = 0;
  double cost_left_ = 0, cost_done_ = 0, prior_rate_ = 0;
};

// The console's output with the tracker's status in front of every record line (the lines
// ConsoleReporter indents by two spaces); other lines pass unchanged.
std::function<void(const std::string&)> with_status(std::function<void(const std::string&)> out,
                                                    const ProgressTracker& tracker);

}  // namespace vob
