#include "harness/bench/sorter_process.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "harness/scene/input_error.h"

extern char** environ;

namespace vob {

namespace {
int millis_until(SorterProcess::Deadline d) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(d - std::chrono::steady_clock::now()).count();
  return ms < 0 ? 0 : static_cast<int>(std::min<long long>(ms, 1 << 30));
}

// write() with SIGPIPE blocked in this thread: a sorter that is gone gives EPIPE, and the
// pending SIGPIPE is consumed so that it is never delivered to vobench.
ssize_t write_no_sigpipe(int fd, const char* p, size_t n) {
  sigset_t pipe_set, old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  const ssize_t w = ::write(fd, p, n);
  const int err = errno;
  if (w < 0 && err == EPIPE) {
    const timespec zero{0, 0};
    while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  errno = err;
  return w;
}
}  // namespace

SorterProcess::SorterProcess(const std::string& command,
                             const std::vector<std::pair<std::string, std::string>>& env,
                             const std::string& stderr_path, const std::string& cleanup_dir) {
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0) throw InputError("command '" + command + "'", "start", std::strerror(errno));
  if (pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    throw InputError("command '" + command + "'", "start", std::strerror(errno));
  }
  const int err = ::open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  // The environment: ours without the protocol's variables, then theirs (built before the
  // spawn: nothing but exec happens in the child).
  std::vector<std::string> vars;
  for (char** e = environ; e && *e; ++e) {
    bool ours = false;
    for (const auto& [k, v] : env) ours = ours || std::strncmp(*e, (k + "=").c_str(), k.size() + 1) == 0;
    if (!ours) vars.emplace_back(*e);
  }
  for (const auto& [k, v] : env) vars.push_back(k + "=" + v);
  std::vector<char*> envp;
  for (auto& v : vars) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::string sh = "sh", dash_c = "-c", cmd = command;
  char* argv[] = {sh.data(), dash_c.data(), cmd.data(), nullptr};

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  if (err >= 0) posix_spawn_file_actions_adddup2(&fa, err, 2);
  posix_spawnattr_t at;
  posix_spawnattr_init(&at);
  posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&at, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&at, &none);
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&defaults, s);
  posix_spawnattr_setsigdefault(&at, &defaults);
  const int rc = posix_spawn(&pid_, "/bin/sh", &fa, &at, argv, envp.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&at);
  ::close(in[0]);
  ::close(out[1]);
  if (err >= 0) ::close(err);
  in_ = in[1];
  out_ = out[0];
  if (rc != 0) {
    ::close(in_);
    ::close(out_);
    in_ = out_ = -1;
    pid_ = -1;
    throw InputError("command '" + command + "'", "start", std::string("cannot run /bin/sh: ") + std::strerror(rc));
  }
  fcntl(in_, F_SETFL, fcntl(in_, F_GETFL) | O_NONBLOCK);
  try {
    start_guard(cleanup_dir);
  } catch (...) {
    kill_group();
    reap();
    ::close(in_);
    ::close(out_);
    throw;
  }
}

void SorterProcess::start_guard(const std::string& cleanup_dir) {
  int p[2];
  if (pipe2(p, O_CLOEXEC) != 0) throw InputError("sorter guard", "start", std::strerror(errno));
  // Its arguments as $1 and $2, never parsed by the shell: any folder name is safe.
  const std::string script =
      "trap '' INT TERM HUP QUIT; read x; [ \"$x\" = done ] && exit 0; "
      "kill -s KILL -- \"-$1\" 2>/dev/null; [ -z \"$2\" ] || rm -rf -- \"$2\"";
  std::string sh = "sh", dash_c = "-c", body = script, name = "vobench-sorter-guard",
              group = std::to_string(pid_), dir = cleanup_dir;
  char* argv[] = {sh.data(), dash_c.data(), body.data(), name.data(), group.data(), dir.data(), nullptr};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, p[0], 0);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t at;
  posix_spawnattr_init(&at);
  posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  posix_spawnattr_setpgroup(&at, 0);  // a group of its own: signals to vobench's group miss it
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&at, &none);
  const int rc = posix_spawn(&guard_, "/bin/sh", &fa, &at, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&at);
  ::close(p[0]);
  if (rc != 0) {
    ::close(p[1]);
    guard_ = -1;
    throw InputError("sorter guard", "start", std::string("cannot run /bin/sh: ") + std::strerror(rc));
  }
  guard_fd_ = p[1];
}

void SorterProcess::dismiss_guard() {
  if (guard_fd_ < 0) return;
  write_no_sigpipe(guard_fd_, "done\n", 5);  // a guard already gone: EPIPE, nothing to do
  ::close(guard_fd_);
  guard_fd_ = -1;
  while (waitpid(guard_, nullptr, 0) < 0 && errno == EINTR) {
  }
}

SorterProcess::~SorterProcess() {
  if (!finished_) finish(2.0);
  if (out_ >= 0) ::close(out_);
}

std::string SorterProcess::finish(double seconds) {
  if (finished_) return "";
  finished_ = true;
  if (in_ >= 0) ::close(in_);  // end of the views: the sorter sees EOF and should exit
  in_ = -1;
  std::string problem;
  if (pid_ > 0 && !wait_for_exit(seconds)) {
    problem = "did not exit within " + std::to_string(static_cast<int>(seconds)) + " s of the end of its input (killed)";
  } else if (pid_ > 0 && (code_ != 0 || signal_ != 0)) {
    problem = exit_description();
  }
  reap();  // whatever the shell left running goes too
  dismiss_guard();
  return problem;
}

bool SorterProcess::wait_for_exit(double seconds) {
  if (exited_ || reaped_ || pid_ <= 0) return true;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    // WNOWAIT: the exited shell stays a zombie, so its id still names the group to kill.
    siginfo_t info{};
    const int r = waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT);
    if (r == 0 && info.si_pid == pid_) {
      exited_ = true;
      if (info.si_code == CLD_EXITED) code_ = info.si_status;
      else signal_ = info.si_status;
      return true;
    }
    if (r < 0 && errno == ECHILD) {
      exited_ = reaped_ = true;
      return true;
    }
    if (std::chrono::steady_clock::now() >= end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void SorterProcess::reap() {
  if (reaped_ || pid_ <= 0) return;
  ::kill(-pid_, SIGKILL);  // the shell, or what it left behind while it is a zombie
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  if (!exited_) {
    exited_ = true;
    if (WIFEXITED(status)) code_ = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) signal_ = WTERMSIG(status);
  }
  reaped_ = true;
}

void SorterProcess::kill_group() {
  if (pid_ > 0 && !reaped_) ::kill(-pid_, SIGKILL);
}

std::string SorterProcess::exit_description() {
  if (!wait_for_exit(1.0)) return "closed its stdout";
  if (signal_ != 0) return "was killed by signal " + std::to_string(signal_) + " (" + strsignal(signal_) + ")";
  return "exited with status " + std::to_string(code_);
}

SorterProcess::Io SorterProcess::write_line(const std::string& line, Deadline deadline) {
  const std::string text = line + "\n";
  size_t done = 0;
  while (done < text.size()) {
    pollfd p{in_, POLLOUT, 0};
    const int r = ::poll(&p, 1, millis_until(deadline));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) return Io::Timeout;
    if (p.revents & (POLLERR | POLLHUP)) return Io::Gone;
    const ssize_t w = write_no_sigpipe(in_, text.data() + done, text.size() - done);
    if (w < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      return Io::Gone;
    }
    done += static_cast<size_t>(w);
  }
  return Io::Ok;
}

SorterProcess::Io SorterProcess::read_line(std::string& line, Deadline deadline, size_t max_bytes) {
  char chunk[1 << 16];
  for (;;) {
    const size_t nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      return Io::Ok;
    }
    if (buffer_.size() > max_bytes) return Io::TooLong;
    pollfd p{out_, POLLIN, 0};
    const int r = ::poll(&p, 1, millis_until(deadline));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) return Io::Timeout;
    const ssize_t n = ::read(out_, chunk, sizeof chunk);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return Io::Gone;
    buffer_.append(chunk, static_cast<size_t>(n));
  }
}

}  // namespace vob
