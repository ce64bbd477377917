// An X server for VTK's OpenGL window (VTK's X render window aborts the process when none
// opens). $DISPLAY when it opens; else, unless told not to, an Xvfb of this run's own
// (Debian package xvfb): started with -displayfd (the server picks a free display, no
// race between runs), in a process group of its own (a terminal's Ctrl-C reaches this
// program, which then stops cleanly, not the server under it), ended with the run and
// by the kernel should this program die (PR_SET_PDEATHSIG). Either way one connection is
// held open for the run: a server started without -noreset (xvfb-run's) resets when its
// last client leaves, and VTK's window, opened during that reset, aborts. Kept apart
// because Xlib's macros (Bool, Status, ...) clash with vobench's names.
#pragma once
#include <stdexcept>
#include <string>

#include <sys/types.h>

struct _XDisplay;

namespace vob {

// Nothing to draw on here (no X server, no Xvfb, Xvfb would not start): exit code 4, so
// that `vobench run` records "not run" rather than a failure.
struct CannotDraw : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class XServer {
 public:
  // `start_xvfb`: may start an Xvfb when $DISPLAY does not open. Throws CannotDraw.
  explicit XServer(bool start_xvfb);
  ~XServer();
  XServer(const XServer&) = delete;
  XServer& operator=(const XServer&) = delete;
  const std::string& description() const { return description_; }  // for render.json

 private:
  void stop();
  _XDisplay* held_ = nullptr;  // open from the constructor to stop(): no server reset
  pid_t pid_ = -1;
  std::string description_;
};

}  // namespace vob
