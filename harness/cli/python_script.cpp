#include "harness/cli/python_script.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>

#include "harness/bench/resources.h"
#include "harness/scene/input_error.h"

extern char** environ;

namespace vob {

int run_python_script(const std::string& script, const std::vector<std::string>& args) {
  std::vector<std::string> all = {VOB_PYTHON, resource_path("reports/" + script)};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw InputError(VOB_PYTHON, script, "cannot start Debian's python3 (install python3-matplotlib)");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 2;
}

std::string gbench_path(const std::string& results) {
  const size_t slash = results.rfind('/'), dot = results.rfind('.');
  const bool ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (ext ? results.substr(0, dot) : results) + ".gbench.json";
}

}  // namespace vob
