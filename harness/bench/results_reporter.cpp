#include "harness/bench/reporters.h"

namespace vob {

ResultsReporter::ResultsReporter(const std::string& path) : file_(path) {}

bool ResultsReporter::done(const std::string& key) { return file_.has(key); }

bool ResultsReporter::report(const Record& rec) { return file_.append(rec.to_json()); }

}  // namespace vob
