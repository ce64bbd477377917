// One scene's views drawn by VTK's projected-tetrahedra mapper with VTK's sort and each
// vobench orderer, interleaved per view and repeat; writes render.json, render.html and
// the images into `out` (vobench-vtk render, for the command line and for suites).
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct RenderSettings {
  std::vector<std::string> algorithms;  // orderer specs, in order
  int repeats = 3;
  double extinction = 1.0;  // times the optical scale of vobench's compositor
  std::function<int()> stop;  // checked before every frame: a signal number stops the run
};

// Thrown by render_scene when `stop` returned a signal: nothing of the scene is written.
struct RenderStopped {
  int signal;
};

// `s` with every byte but letters, digits, '-' and '.' as '_' (file and folder names).
std::string file_label(const std::string& s);

// `context`: what names the run (scene spec, command line); completed and written to
// render.json. Returns the per-sorter summary (render_report.h).
nlohmann::json render_scene(const Scene& scene, const std::vector<std::pair<int, Camera>>& cameras,
                            const RenderSettings& settings, const std::string& out, nlohmann::json context);

}  // namespace vob
