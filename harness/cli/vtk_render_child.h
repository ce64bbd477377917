// A suite's "vtk_render" entry, drawn by `vobench run` and `vobench reproduce` after the
// suite's records: they start the vobench-vtk program (VTK's OpenGL modules stay out of this
// process) as `vobench-vtk render --suite OUT/vtk/suite-NAME.json -o OUT`. It is looked for
// in $VOBENCH_VTK, else beside this program (build tree and installed bin/ alike); it finds
// an X server itself ($DISPLAY, else an Xvfb of its own). Its output is passed through to
// stderr. OUT/vtk/status-NAME.json records the outcome for `vobench report` ("What VTK
// shows"): done, not run (no vobench-vtk, nothing to draw on: its exit 4), interrupted, or
// failed, each with the reason. A stop signal is passed on to it (it runs in a process group
// of its own, so a terminal's Ctrl-C reaches this program only, once): it stops after the
// frame in progress and keeps every finished scene; the records are never touched.
#pragma once
#include <string>

#include "harness/bench/suite.h"

namespace vob {

// Returns 0 when done or not run here, 128 + signal when a stop signal ended it, else
// vobench-vtk's failing exit status. Nothing happens without a vtk_render entry. Call it
// while a StopSignals is installed.
int run_vtk_render(const SuiteSpec& suite, const std::string& out_dir);

}  // namespace vob
