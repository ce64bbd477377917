#include "harness/cli/vtk_render_child.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "harness/bench/atomic_file.h"
#include "harness/cli/stop_signals.h"

namespace vob {

namespace fs = std::filesystem;

namespace {
std::string file_part(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return o;
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

// $VOBENCH_VTK, else vobench-vtk beside this program; "" (and where it looked) when absent.
std::string find_program(std::string& looked) {
  if (const char* env = std::getenv("VOBENCH_VTK"); env && *env) {
    looked = std::string("$VOBENCH_VTK '") + env + "'";
    return access(env, X_OK) == 0 ? env : "";
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const std::string beside = ec ? std::string("vobench-vtk") : (self.parent_path() / "vobench-vtk").string();
  looked = "'" + beside + "'";
  return access(beside.c_str(), X_OK) == 0 ? beside : "";
}

struct Outcome {
  int status = 0;     // exit status, or 128 + signal
  std::string last;   // its last line of output
  int forwarded = 0;  // the stop signal passed on, 0 when none
};

// Starts `argv` in a process group of its own with stdout and stderr into a pipe we copy
// to our stderr, passes a stop signal on once, and waits.
Outcome run_child(const std::vector<std::string>& args) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("vtk_render: cannot make a pipe");
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("vtk_render: cannot fork");
  if (pid == 0) {  // async-signal-safe calls only until exec
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // this process gone: the child stops too
    if (getppid() != parent) _exit(126);
    dup2(fds[1], 1);
    dup2(fds[1], 2);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(fds[1]);
  Outcome o;
  std::string line;
  pollfd p{fds[0], POLLIN, 0};
  for (;;) {
    if (const int sig = StopSignals::received(); sig && !o.forwarded) {
      kill(pid, sig);
      o.forwarded = sig;
    }
    const int r = poll(&p, 1, 100);
    if (r <= 0) continue;  // timeout or EINTR: look at the signals again
    char buf[4096];
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EOF: the child (and anything it started) closed its output
    std::cerr.write(buf, n).flush();
    for (ssize_t i = 0; i < n; ++i) {
      if (buf[i] != '\n') {
        line += buf[i];
      } else if (!line.empty()) {
        o.last = line;
        line.clear();
      }
    }
  }
  if (!line.empty()) o.last = line;
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  o.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return o;
}
}  // namespace

int run_vtk_render(const SuiteSpec& suite, const std::string& out_dir) {
  if (!suite.vtk_render) return 0;
  const std::string dir = (fs::path(out_dir) / "vtk").string();
  const std::string name = file_part(suite.name);
  const std::string status_path = dir + "/status-" + name + ".json";
  nlohmann::json status = {{"suite", suite.name}, {"started", now_utc()}, {"state", "running"}};
  const auto finish = [&](const std::string& state, const std::string& reason) {
    status["state"] = state;
    status["reason"] = reason;
    status["finished"] = now_utc();
    write_file_atomically(status_path, status.dump(1) + "\n");
    std::cerr << "vtk_render: " << suite.name << ": " << state << (reason.empty() ? "" : ": " + reason) << "\n";
  };
  std::string looked;
  const std::string program = find_program(looked);
  if (program.empty()) {
    finish("not run", "vobench-vtk not found (looked for " + looked + ")");
    return 0;
  }
  const std::string suite_file = dir + "/suite-" + name + ".json";
  write_file_atomically(suite_file, suite.source.dump(1) + "\n");
  const std::vector<std::string> args = {program, "render", "--suite", suite_file, "-o", out_dir};
  std::string command;
  for (const auto& a : args) command += (command.empty() ? "" : " ") + a;
  status["command"] = command;
  write_file_atomically(status_path, status.dump(1) + "\n");
  std::cerr << "vtk_render: " << suite.name << ": " << command << "\n";
  const Outcome o = run_child(args);
  status["exit"] = o.status;
  const int sig = o.forwarded ? o.forwarded : (o.status == 130 ? SIGINT : o.status == 143 ? SIGTERM : 0);
  if (o.status == 0) {
    finish("done", "");
    return 0;
  }
  if (sig) {
    finish("interrupted", std::string("stopped by ") + StopSignals::name(sig) +
                              "; finished scenes are kept: run the same command again to draw the rest");
    return StopSignals::exit_code(sig);
  }
  if (o.status == 4) {
    finish("not run", o.last);
    return 0;
  }
  finish("failed", "exit " + std::to_string(o.status) + (o.last.empty() ? "" : ": " + o.last));
  return o.status;
}

}  // namespace vob
