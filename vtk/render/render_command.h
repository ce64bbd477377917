// `vobench-vtk render`: a scene and its views drawn by vtkOpenGLProjectedTetrahedraMapper,
// once with VTK's own sort (vtkCellCenterDepthSort) and once per vobench orderer given
// (render_scene.h); or, with --suite, every cell dataset and size of a suite with the
// orderers its "vtk_render" entry names, into OUT/vtk/LABEL-WxH/, where `vobench report
// OUT` finds them ("What VTK shows"). A suite's scene goes to LABEL-WxH.partial first and is
// renamed into place when complete, so an interrupted run leaves every finished scene as it
// was and no half scene; a scene whose render.json has the same run_key is kept (resume).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/cli/scene_args.h"
#include "vtk/render/render_scene.h"

namespace vob {

struct RenderArgs {
  SceneArgs scene;
  ViewArgs view;
  RenderSettings settings;
  std::vector<std::string> externals;  // NAME=COMMAND: external sorters, usable as NAME
  double timeout = 60.0;
  std::string suite;
  std::string out;
  std::string xvfb = "auto";  // auto: start an Xvfb when no X server opens; never
  void add_to(CLI::App& cmd);
  CLI::App* cmd = nullptr;
};

int run_render(const RenderArgs& args, const std::string& command_line);

}  // namespace vob
