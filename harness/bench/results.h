// A results file: one JSON record per line (JSONL), shared safely by every process that
// writes it. Each record reaches the file when it is appended, as one write() of a whole
// line at the end of the file under an exclusive flock(2) on the file, followed by
// fdatasync. Lines already in the file are never rewritten, so a run that is interrupted or
// killed loses at most the record it was computing, and two runs writing one file keep both
// runs' records. Under the same lock the lines other processes appended since the last look
// are read first, so a key is never written twice.
//
// A last line without its newline can only be left by a writer that died mid-write (every
// write holds the lock). The next look, under the lock, repairs it and prints one note line:
// a whole JSON record just gets its newline back; anything else is cut off. A malformed
// line that ends in a newline is bad input (InputError), never repaired.
#pragma once
#include <sys/types.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vob {

class ResultsFile {
 public:
  // Opens or creates the file (mode 0666 & ~umask, parent folders created) and reads its
  // keys. InputError (one line) when the file or its folder cannot be created or written,
  // or when a line is not a JSON record.
  explicit ResultsFile(std::string path);
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  // Whether a record with this key is in the file, including records other processes
  // appended since the last look.
  bool has(const std::string& key);
  // Appends the record (it must carry a string "key") unless a record with its key is in
  // the file already; returns whether it was written.
  bool append(const nlohmann::json& record);
  // Takes out the records and plan lines for which `drop` holds and returns them; context
  // lines and every other line stay, in file order. The only rewrite of a results file (`--force` on one
  // reproduction of a shared folder): under the lock the kept lines go to a new file that
  // is renamed over this one, so a reader sees the old file or the new one, and a writer
  // holding the old one finds it replaced at its next lock and reads the new one.
  std::vector<nlohmann::json> remove_records(const std::function<bool(const nlohmann::json&)>& drop);
  // Records in the file as of the last look.
  size_t size() const { return records_; }
  const std::string& path() const { return path_; }

  // Every record of a results file, in file order, without the runs' context lines
  // (context.h) and the suites' plan lines (job_plan.h). InputError for a line that is not JSON.
  // `torn_tail_ok`: a last line without its newline that is not JSON (a writer killed
  // mid-line; the next ResultsFile removes it) is left out instead of refused, for the
  // readers that plan a run before its writer opens the file.
  static std::vector<nlohmann::json> read_all(const std::string& path, bool torn_tail_ok = false);
  // The same with the context and plan lines, where they stand.
  static std::vector<nlohmann::json> read_all_lines(const std::string& path, bool torn_tail_ok = false);

 private:
  class Lock;
  void open_file();
  void forget_contents();
  void read_new_lines();  // with the lock held

  std::string path_;
  int fd_ = -1;
  off_t read_to_ = 0;     // bytes looked at so far, always just after a newline
  size_t lines_ = 0;      // lines looked at so far (for line numbers in messages)
  size_t records_ = 0;
  std::set<std::string> keys_;
};

}  // namespace vob
