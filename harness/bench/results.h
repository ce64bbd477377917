// A results file: one JSON record per line (JSONL). append() keeps a record in memory;
// flush() rewrites the whole file atomically (temporary file, then rename), so an
// interrupted run leaves the records flushed so far and nothing half-written; a rerun skips
// records whose "key" is already present. The runner flushes after every (algorithm,
// dataset) pair; the destructor flushes what is left.
#pragma once
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vob {

class ResultsFile {
 public:
  explicit ResultsFile(std::string path);  // loads existing records; bad lines: InputError
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;
  bool has(const std::string& key) const { return keys_.count(key) > 0; }
  void append(const nlohmann::json& record);  // record must carry a string "key"
  void flush();
  size_t size() const { return lines_.size(); }
  const std::string& path() const { return path_; }
  static std::vector<nlohmann::json> read_all(const std::string& path);

 private:
  std::string path_;
  std::vector<std::string> lines_;
  std::set<std::string> keys_;
  bool dirty_ = false;
};

}  // namespace vob
