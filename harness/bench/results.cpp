#include "harness/bench/results.h"

#include <algorithm>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/json_input.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::string reason(int err) { return std::strerror(err); }

bool blank(std::string_view s) { return s.find_first_not_of(" \t\r") == std::string_view::npos; }

// The whole text is one JSON object (depth-bounded like every outside JSON).
bool whole_record(std::string_view text) {
  if (json_nesting_depth(text) > kMaxJsonDepth || !nlohmann::json::accept(text)) return false;
  return nlohmann::json::parse(text).is_object();
}

bool write_all(int fd, std::string_view s) {
  while (!s.empty()) {
    const ssize_t n = ::write(fd, s.data(), s.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    s.remove_prefix(size_t(n));
  }
  return true;
}
}  // namespace

// An exclusive flock on the open file for as long as it lives. Every writer appends under
// it, so while it is held nobody is half-way through a line. When the path no longer names
// the file we hold (removed or replaced, e.g. by `reproduce --force` in another process),
// the file now at the path is opened and read from its first line.
class ResultsFile::Lock {
 public:
  explicit Lock(ResultsFile& f) : f_(f) {
    for (;;) {
      while (::flock(f_.fd_, LOCK_EX) != 0)
        if (errno != EINTR) throw InputError(f_.path_, "results", "cannot be locked: " + reason(errno));
      struct stat named {}, held {};
      if (::stat(f_.path_.c_str(), &named) == 0 && ::fstat(f_.fd_, &held) == 0 &&
          named.st_dev == held.st_dev && named.st_ino == held.st_ino)
        return;
      ::flock(f_.fd_, LOCK_UN);
      ::close(f_.fd_);
      f_.fd_ = -1;
      f_.forget_contents();
      f_.open_file();
    }
  }
  ~Lock() { ::flock(f_.fd_, LOCK_UN); }
  Lock(const Lock&) = delete;
  Lock& operator=(const Lock&) = delete;

 private:
  ResultsFile& f_;
};

std::vector<nlohmann::json> ResultsFile::read_all_lines(const std::string& path, bool torn_tail_ok) {
  std::vector<nlohmann::json> out;
  std::ifstream in(path);
  if (!in) throw InputError(path, "results", "cannot be read");
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (blank(line)) continue;
    // getline stopped at the end of the file, not at a newline: the last line is unfinished.
    if (torn_tail_ok && in.eof() && !nlohmann::json::accept(line)) break;
    out.push_back(parse_json_input(line, path, "line " + std::to_string(n)));
  }
  return out;
}

std::vector<nlohmann::json> ResultsFile::read_all(const std::string& path, bool torn_tail_ok) {
  std::vector<nlohmann::json> out = read_all_lines(path, torn_tail_ok);
  out.erase(std::remove_if(out.begin(), out.end(), [](const nlohmann::json& r) { return is_meta_line(r); }),
            out.end());
  return out;
}

ResultsFile::ResultsFile(std::string path) : path_(std::move(path)) {
  open_file();
  try {
    Lock lock(*this);
    read_new_lines();
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

ResultsFile::~ResultsFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsFile::open_file() {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path_).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) throw InputError(path_, "results folder", "cannot be created: " + ec.message());
  }
  // O_APPEND: every write lands at the end, whatever another process wrote before it.
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
  if (fd_ < 0) throw InputError(path_, "results", "cannot be opened for writing: " + reason(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(path_, "results", "is not a regular file");
  }
}

void ResultsFile::forget_contents() {
  read_to_ = 0;
  lines_ = 0;
  records_ = 0;
  keys_.clear();
}

void ResultsFile::read_new_lines() {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) throw InputError(path_, "results", "cannot be read: " + reason(errno));
  if (st.st_size < read_to_) forget_contents();  // truncated by someone else: start over
  if (st.st_size == read_to_) return;
  std::string buf(size_t(st.st_size - read_to_), '\0');
  for (size_t got = 0; got < buf.size();) {
    const ssize_t n = ::pread(fd_, buf.data() + got, buf.size() - got, read_to_ + off_t(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(path_, "results", "cannot be read: " + reason(n < 0 ? errno : EIO));
    got += size_t(n);
  }
  auto take = [&](std::string_view line) {
    const std::string where = "line " + std::to_string(lines_);
    if (blank(line)) return;
    const nlohmann::json r = parse_json_input(line, path_, where);
    if (!r.is_object()) throw InputError(path_, where, "is not a JSON object");
    if (!r.contains("key")) throw InputError(path_, where, "is not a results record (no \"key\")");
    if (!r["key"].is_string()) throw InputError(path_, where, "\"key\" is not a string");
    ++records_;
    keys_.insert(r["key"].get<std::string>());
  };
  size_t start = 0;
  for (size_t nl; (nl = buf.find('\n', start)) != std::string::npos; start = nl + 1) {
    ++lines_;
    take(std::string_view(buf).substr(start, nl - start));
  }
  read_to_ += off_t(start);
  if (start == buf.size()) return;

  // A last line without its newline: a writer died mid-write (see results.h).
  const std::string_view tail = std::string_view(buf).substr(start);
  const std::string where = path_ + ": line " + std::to_string(lines_ + 1);
  if (whole_record(tail)) {
    if (!write_all(fd_, "\n")) throw InputError(path_, "results", "cannot be written: " + reason(errno));
    ++lines_;
    take(tail);
    read_to_ += off_t(tail.size() + 1);
    std::cerr << "vobench: note: " << where << ": a whole record without its newline; newline added\n";
  } else {
    if (::ftruncate(fd_, read_to_) != 0)
      throw InputError(path_, "results", "cannot be written: " + reason(errno));
    std::cerr << "vobench: note: " << where << ": an incomplete last line (" << tail.size()
              << " bytes, left by an interrupted writer) removed\n";
  }
}

bool ResultsFile::has(const std::string& key) {
  Lock lock(*this);
  read_new_lines();
  return keys_.count(key) > 0;
}

bool ResultsFile::append(const nlohmann::json& record) {
  if (!record.is_object() || !record.contains("key") || !record["key"].is_string())
    throw std::logic_error("ResultsFile::append: a record needs a string \"key\"");
  const std::string key = record["key"].get<std::string>();
  const std::string line = record.dump() + "\n";
  Lock lock(*this);
  read_new_lines();
  if (keys_.count(key)) return false;
  if (!write_all(fd_, line)) {
    const int err = errno;
    // Leave no partial line behind: nobody else writes while we hold the lock.
    const bool cut = ::ftruncate(fd_, read_to_) == 0;
    throw InputError(path_, "results", "cannot be written: " + reason(err) +
                                           (cut ? "" : " (the next run removes the partial line)"));
  }
  if (::fdatasync(fd_) != 0) throw InputError(path_, "results", "cannot be flushed to disk: " + reason(errno));
  read_to_ += off_t(line.size());
  ++lines_;
  ++records_;
  keys_.insert(key);
  return true;
}

std::vector<nlohmann::json> ResultsFile::remove_records(const std::function<bool(const nlohmann::json&)>& drop) {
  std::vector<nlohmann::json> removed;
  {
    Lock lock(*this);
    read_new_lines();  // a torn last line repaired first
    std::string buf(size_t(read_to_), '\0');
    for (size_t got = 0; got < buf.size();) {
      const ssize_t n = ::pread(fd_, buf.data() + got, buf.size() - got, off_t(got));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw InputError(path_, "results", "cannot be read: " + reason(n < 0 ? errno : EIO));
      got += size_t(n);
    }
    std::string kept;
    size_t line_no = 0;
    for (size_t start = 0, nl; (nl = buf.find('\n', start)) != std::string::npos; start = nl + 1) {
      ++line_no;
      const std::string_view line = std::string_view(buf).substr(start, nl - start);
      if (blank(line)) continue;
      nlohmann::json r = parse_json_input(line, path_, "line " + std::to_string(line_no));
      if (!is_context_line(r) && drop(r)) {
        removed.push_back(std::move(r));
      } else {
        kept.append(line);
        kept.push_back('\n');
      }
    }
    if (removed.empty()) return removed;
    write_file_atomically(path_, kept);
  }
  // Our descriptor still names the old file: look again from the start of the new one.
  ::close(fd_);
  fd_ = -1;
  forget_contents();
  open_file();
  Lock lock(*this);
  read_new_lines();
  return removed;
}

}  // namespace vob
