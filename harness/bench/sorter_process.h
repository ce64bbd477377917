// The child process of an external sorter (external_orderer.h): started through /bin/sh -c
// in its own process group (a timeout kills the shell and what it started), stdin and
// stdout are pipes, stderr goes to a file (its last line explains a crash in one line).
// Reads and writes wait at most until a deadline; SIGPIPE never reaches vobench.
// Nothing the sorter started outlives vobench: at the end its whole group is killed (a
// background child of the shell included), and a guard process (a shell in a group of its
// own, deaf to SIGINT/SIGTERM/SIGHUP) waits on a pipe that only vobench holds open: when
// vobench dies without saying "done" (Ctrl-C, a CI job's timeout, SIGKILL), the guard
// kills the sorter's group and removes `cleanup_dir`.
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
                const std::string& stderr_path, const std::string& cleanup_dir = "");
  ~SorterProcess();  // finish(2 s) unless called: the group killed, the guard dismissed
  SorterProcess(const SorterProcess&) = delete;
  SorterProcess& operator=(const SorterProcess&) = delete;

  Io write_line(const std::string& line, Deadline deadline);  // `line` without '\n'
  // The line without '\n'; TooLong once more than max_bytes arrive without a newline.
  Io read_line(std::string& line, Deadline deadline, size_t max_bytes);
  // "exited with status 1", "was killed by signal 11 (Segmentation fault)", or "closed its
  // stdout" while still running; waits up to a second for the exit.
  std::string exit_description();
  void kill_group();
  // The end of the views: closes the sorter's stdin and waits up to `seconds` for the
  // shell to exit; then kills whatever is left of its group. "" when it exited with status
  // 0, else what went wrong ("exited with status 1", "did not exit within 2 s of the end
  // of its input (killed)").
  std::string finish(double seconds);

 private:
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1;  // our ends: the sorter's stdin and stdout
  std::string buffer_;      // bytes read past the last line
  bool exited_ = false;     // the shell has exited (seen, not yet reaped: its id still names the group)
  bool reaped_ = false;
  int code_ = 0, signal_ = 0;  // its exit status, or the signal that ended it
  pid_t guard_ = -1;
  int guard_fd_ = -1;       // our end of the guard's stdin
  bool finished_ = false;
  bool wait_for_exit(double seconds);  // without reaping
  void reap();                          // kills the group's leftovers, then reaps the shell
  void start_guard(const std::string& cleanup_dir);
  void dismiss_guard();
};

}  // namespace vob
