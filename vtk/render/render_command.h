// `vobench-vtk render`: a scene and its views drawn by vtkOpenGLProjectedTetrahedraMapper,
// once with VTK's own sort (vtkCellCenterDepthSort) and once per vobench orderer given,
// interleaved per view and repeat; images, differences from the first exact orderer's
// image, frame and sort times (render.json, render.html).
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/cli/scene_args.h"

namespace vob {

struct RenderArgs {
  SceneArgs scene;
  ViewArgs view;
  std::vector<std::string> algorithms;  // orderer specs, in order
  std::vector<std::string> externals;   // NAME=COMMAND: external sorters, usable as NAME
  double timeout = 60.0;
  int repeats = 3;
  double extinction = 1.0;  // times the optical scale of vobench's compositor
  std::string out;
  void add_to(CLI::App& cmd);
};

int run_render(const RenderArgs& args, const std::string& command_line);

}  // namespace vob
