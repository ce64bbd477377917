#include "harness/bench/reporters.h"

namespace vob {

ResultsReporter::ResultsReporter(const std::string& path, nlohmann::json context)
    : file_(path), context_(std::move(context)) {}

bool ResultsReporter::done(const std::string& key) { return file_.has(key); }

bool ResultsReporter::report(const Record& rec) {
  // A run that writes nothing leaves no context line; one that writes has it first.
  if (!context_.is_null()) {
    file_.append(context_);
    context_ = nullptr;
  }
  return file_.append(rec.to_json());
}

}  // namespace vob
