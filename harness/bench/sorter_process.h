// The child process of an external sorter (external_orderer.h): started through /bin/sh -c
// in its own process group (a timeout kills the shell and what it started), stdin and
// stdout are pipes, stderr goes to a file (its last line explains a crash in one line).
// Reads and writes wait at most until a deadline; SIGPIPE never reaches vobench.
#pragma once
#include <chrono>
#include <string>
#include <sys/types.h>
#include <utility>
#include <vector>

namespace vob {

class SorterProcess {
 public:
  using Deadline = std::chrono::steady_clock::time_point;
  enum class Io { Ok, Gone, Timeout, TooLong };

  // Throws InputError naming the command when it cannot be started.
  SorterProcess(const std::string& command, const std::vector<std::pair<std::string, std::string>>& env,
                const std::string& stderr_path);
  ~SorterProcess();  // closes stdin, waits a moment for the exit, then kills the group
  SorterProcess(const SorterProcess&) = delete;
  SorterProcess& operator=(const SorterProcess&) = delete;

  Io write_line(const std::string& line, Deadline deadline);  // `line` without '\n'
  // The line without '\n'; TooLong once more than max_bytes arrive without a newline.
  Io read_line(std::string& line, Deadline deadline, size_t max_bytes);
  // "exited with status 1", "was killed by signal 11 (Segmentation fault)", or "closed its
  // stdout" while still running; waits up to a second for the exit.
  std::string exit_description();
  void kill_group();

 private:
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1;  // our ends: the sorter's stdin and stdout
  std::string buffer_;      // bytes read past the last line
  bool reaped_ = false;
  int status_ = 0;
  bool wait_for_exit(double seconds);
};

}  // namespace vob
