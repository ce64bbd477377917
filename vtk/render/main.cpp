// vobench-vtk: vobench's orderers inside VTK's own renderer (issue 18). A program apart from
// vobench: it links VTK's OpenGL modules, which the OSMesa vobench program never does.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "harness/cli/error_line.h"
#include "harness/cli/stop_signals.h"
#include "harness/scene/input_error.h"
#include "vtk/render/render_command.h"
#include "vtk/render/x_display.h"

int main(int argc, char** argv) {
  CLI::App app{"vobench-vtk: scenes drawn by VTK's projected-tetrahedra mapper with VTK's and vobench's sorts"};
  app.require_subcommand(1);
  vob::RenderArgs args;
  CLI::App* render = app.add_subcommand(
      "render", "draw a scene's views with vtkOpenGLProjectedTetrahedraMapper, with VTK's sort and each "
                "--algorithm; writes render.json, render.html and the images (an X server: $DISPLAY, else an Xvfb it starts)");
  args.add_to(*render);
  // One line on stderr, exit 2 (3 for an internal error), as the vobench program; 4 when
  // nothing can be drawn here (no X server, no Xvfb); 130 / 143 when stopped by a signal.
  const auto fail = [&](const std::string& message, int code) {
    std::fprintf(stderr, "%s\n", vob::error_line("vobench-vtk: render: " + message).c_str());
    return code;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    return fail(e.what(), 2);
  }
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  try {
    return vob::run_render(args, line);
  } catch (const vob::RenderStopped& e) {
    std::fprintf(stderr, "vobench-vtk: render: stopped by %s; every finished scene is kept\n",
                 vob::StopSignals::name(e.signal));
    return vob::StopSignals::exit_code(e.signal);
  } catch (const vob::CannotDraw& e) {
    return fail(e.what(), 4);
  } catch (const vob::InputError& e) {
    return fail(e.what(), 2);
  } catch (const std::logic_error& e) {
    return fail(std::string("internal error: ") + e.what(), 3);
  } catch (const std::exception& e) {
    return fail(e.what(), 2);
  }
}
