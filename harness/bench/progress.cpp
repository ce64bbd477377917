#include "harness/bench/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vob {

ProgressTracker::ProgressTracker(ProgressTracker* parent) : parent_(parent) {}

void ProgressTracker::add(size_t jobs, double cost_to_do) {
  jobs_ += jobs;
  cost_left_ += cost_to_do;
}

void ProgressTracker::replace(size_t old_jobs, double old_cost, size_t jobs, double cost) {
  jobs_ = jobs_ + jobs - std::min(jobs_, old_jobs);
  cost_left_ = std::max(0.0, cost_left_ - old_cost + cost);
  if (parent_) parent_->replace(old_jobs, old_cost, jobs, cost);
}

void ProgressTracker::skipped(double cost) {
  ++done_;
  cost_left_ = std::max(0.0, cost_left_ - cost);
  if (parent_) parent_->skipped(cost);
}

void ProgressTracker::finished(double cost) {
  ++done_;
  cost_done_ += cost;
  cost_left_ = std::max(0.0, cost_left_ - cost);
  if (parent_) parent_->finished(cost);
}

std::string ProgressTracker::clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", s / 60, s % 60);
  return buf;
}

double ProgressTracker::seconds_left() const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The run's own rate once it has computed a job (scene generation included in the
  // elapsed time, so it is spread over the jobs); before that, earlier records' rate.
  const double rate = cost_done_ > 0 ? elapsed / cost_done_ : prior_rate_;
  return rate > 0 ? rate * cost_left_ : -1;
}

std::string ProgressTracker::count_text() const {
  return "[" + std::to_string(done_) + "/" + std::to_string(jobs_) + "]";
}

std::string ProgressTracker::status() const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left = seconds_left();
  std::string s = count_text() + " " + clock_text(elapsed) + " elapsed, " +
                  (left < 0 ? std::string("time left unknown") : "~" + clock_text(left) + " left");
  if (parent_) {
    const double all = parent_->seconds_left();
    s += " (all: " + parent_->count_text() + (all < 0 ? "" : ", ~" + clock_text(all) + " left") + ")";
  }
  return s;
}

std::function<void(const std::string&)> with_status(std::function<void(const std::string&)> out,
                                                    const ProgressTracker& tracker) {
  if (!out) return out;
  return [out, &tracker](const std::string& line) {
    out(line.rfind("  ", 0) == 0 ? tracker.status() + ": " + line.substr(2) : line);
  };
}

}  // namespace vob
