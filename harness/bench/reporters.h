// The runner's reporters, one per output (in the manner of Google Benchmark's reporters):
// the results file, the console progress lines and the image files. Each is in its own
// file (results_reporter.cpp, console_reporter.cpp, image_reporter.cpp).
#pragma once
#include <functional>
#include <string>

#include "harness/bench/measure.h"
#include "harness/bench/results.h"
#include "harness/bench/suite.h"

namespace vob {

// Appends records to the results file (results.h: under flock, never rewriting a line).
class ResultsReporter {
 public:
  // `context`: the run's context line (context.h), appended before the run's first record.
  ResultsReporter(const std::string& path, nlohmann::json context);
  bool done(const std::string& key);
  // Whether the record was written (false: another process appended its key first).
  bool report(const Record& rec);

 private:
  ResultsFile file_;
  nlohmann::json context_;  // null once written
};

// One progress line per dataset and per record.
class ConsoleReporter {
 public:
  explicit ConsoleReporter(std::function<void(const std::string&)> out) : out_(std::move(out)) {}
  void dataset(size_t index, size_t count, const std::string& label, const Scene& scene, double seconds) const;
  void record(const Record& rec, bool written) const;
  void say(const std::string& line) const {
    if (out_) out_(line);
  }

 private:
  std::function<void(const std::string&)> out_;
};

// Renders a record's order and the exact image when the suite wants its image error or
// its images: fills image_error, writes the PNGs (order, exact, diff, and violations when
// the verdict has a mask) and names them in images, relative to results_dir (the folder
// holding results.jsonl).
class ImageReporter {
 public:
  ImageReporter(const SuiteSpec& suite, std::string image_dir, std::string results_dir);
  bool writes_files() const;  // the suite may write PNGs (the folder must be writable)
  void report(Measurement& m, const Scene& scene, const Camera& camera) const;

 private:
  const SuiteSpec& suite_;
  std::string dir_, results_dir_;
};

}  // namespace vob
