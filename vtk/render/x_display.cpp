#include "vtk/render/x_display.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include <X11/Xlib.h>

namespace vob {

namespace {
std::string display_env() {
  const char* name = std::getenv("DISPLAY");
  return std::string("'") + (name ? name : "") + "'";
}

// The display number Xvfb writes to `fd` once it accepts connections, "" on EOF or after
// `seconds`.
std::string read_display_number(int fd, int seconds) {
  std::string got;
  pollfd p{fd, POLLIN, 0};
  for (int waited = 0; waited < seconds * 10;) {
    const int r = poll(&p, 1, 100);
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) {
      ++waited;
      continue;
    }
    char buf[32];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return "";
    got.append(buf, static_cast<size_t>(n));
    if (got.find('\n') != std::string::npos) return got.substr(0, got.find('\n'));
  }
  return "";
}
}  // namespace

XServer::XServer(bool start_xvfb) {
  held_ = XOpenDisplay(nullptr);
  if (held_) {
    description_ = "DISPLAY=" + std::string(std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "");
    return;
  }
  if (!start_xvfb)
    throw CannotDraw("DISPLAY " + display_env() + ": no X server opens (--xvfb never)");
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw CannotDraw("cannot make a pipe for Xvfb");
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw CannotDraw("cannot fork to start Xvfb");
  if (pid == 0) {  // only async-signal-safe calls until exec
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(126);
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0);
    dup2(null, 1);
    dup2(null, 2);
    dup2(fds[1], 3);  // dup2 clears close-on-exec on the copy
    // -noreset: without it the server resets when our probe's connection closes, and VTK's
    // connection, made during that reset, fails now and then.
    execlp("Xvfb", "Xvfb", "-displayfd", "3", "-screen", "0", "2048x2048x24", "-nolisten", "tcp", "-noreset",
           nullptr);
    _exit(127);
  }
  close(fds[1]);
  const std::string number = read_display_number(fds[0], 20);
  close(fds[0]);
  if (number.empty()) {
    kill(pid, SIGTERM);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
      throw CannotDraw("DISPLAY " + display_env() +
                       ": no X server opens and no Xvfb to start one (Debian package xvfb)");
    throw CannotDraw("DISPLAY " + display_env() + ": no X server opens and Xvfb did not start");
  }
  pid_ = pid;
  setenv("DISPLAY", (":" + number).c_str(), 1);
  description_ = "Xvfb :" + number + " (started for this run)";
  held_ = XOpenDisplay(nullptr);
  if (!held_) {
    stop();
    throw CannotDraw("Xvfb :" + number + " started but does not open");
  }
}

XServer::~XServer() { stop(); }

void XServer::stop() {
  if (held_) XCloseDisplay(held_);
  held_ = nullptr;
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
}

}  // namespace vob
