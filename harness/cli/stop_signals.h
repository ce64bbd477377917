// SIGINT and SIGTERM during `vobench run` and `vobench reproduce`: the first one asks the
// runner to stop after the record in progress (every finished record is already on disk,
// see harness/bench/results.h); the handler then steps aside (SA_RESETHAND), so a second
// signal ends the process at once, losing only the record in progress.
#pragma once

namespace vob {

class StopSignals {
 public:
  StopSignals();   // installs the handlers
  ~StopSignals();  // puts the previous handlers back
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // 0 until a signal arrived, then SIGINT or SIGTERM.
  static int received();
  // The shell's convention for a process ended by a signal: 130 for SIGINT, 143 for SIGTERM.
  static int exit_code(int signal) { return 128 + signal; }
  static const char* name(int signal);
};

}  // namespace vob
