#include "harness/bench/results.h"

#include <filesystem>
#include <fstream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/json_input.h"
#include "harness/scene/input_error.h"

namespace vob {

std::vector<nlohmann::json> ResultsFile::read_all(const std::string& path) {
  std::vector<nlohmann::json> out;
  std::ifstream in(path);
  if (!in) throw InputError(path, "results", "cannot be read");
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty()) continue;
    out.push_back(parse_json_input(line, path, "line " + std::to_string(n)));
  }
  return out;
}

ResultsFile::ResultsFile(std::string path) : path_(std::move(path)) {
  if (!std::filesystem::exists(path_)) return;
  for (const auto& r : read_all(path_)) {
    lines_.push_back(r.dump());
    if (r.contains("key")) keys_.insert(r["key"].get<std::string>());
  }
}

void ResultsFile::append(const nlohmann::json& record) {
  lines_.push_back(record.dump());
  keys_.insert(record.at("key").get<std::string>());
  dirty_ = true;
}

void ResultsFile::flush() {
  if (!dirty_) return;
  std::string content;
  for (const auto& l : lines_) content += l + "\n";
  write_file_atomically(path_, content);
  dirty_ = false;
}

ResultsFile::~ResultsFile() {
  try {
    flush();
  } catch (const std::exception&) {
    // A destructor must not throw; run_suite flushes explicitly and reports errors there.
  }
}

}  // namespace vob
