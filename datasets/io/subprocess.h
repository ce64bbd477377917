// Runs a program without a shell (posix_spawn), in a given folder, with its output sent to
// files, and never waits forever: past the deadline the child is killed.
#pragma once
#include <string>
#include <vector>

namespace vob {

struct ProcessResult {
  int exit_code = -1;    // valid when exited
  bool exited = false;   // normal exit
  int signal = 0;        // the signal that ended it, if any
  bool timed_out = false;
};

// argv[0] is the program path. stdout_path / stderr_path: files to create ("" = /dev/null).
// InputError naming the program when it cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& cwd,
                          const std::string& stdout_path, const std::string& stderr_path,
                          double timeout_seconds);

// The last non-empty line of a text file ("" if none or unreadable), for error messages.
std::string last_line_of(const std::string& path);

}  // namespace vob
