// What `vobench-vtk render` measured, and its two outputs: render.json (everything,
// machine-readable) and render.html (the images side by side, one row per view).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/view/camera.h"
#include "vtk/render/image_compare.h"

namespace vob {

struct SorterInfo {
  std::string label;      // "vtk-default" or the orderer spec
  std::string algorithm;  // "vtkCellCenterDepthSort" or the orderer spec
  bool object_exact = false, image_exact = false;
  double prepare_seconds = -1;  // vobench orderers: the adapter's prepare on the warm-up frame;
                                // -1 for VTK's (its cell centres are made inside the first sort)
};

struct SorterFrame {
  std::vector<double> frame_seconds, sort_seconds;  // one per repeat
  std::string image;                                // file name in the output folder
  int64_t covered = 0;                              // pixels not background (black)
  bool compared = false;                            // a reference exists
  PixelDiff diff;
  std::string diff_image;
};

struct ViewFrames {
  int view_index = -1;
  Camera camera;
  std::vector<SorterFrame> sorters;  // as RenderRun::sorters
};

struct RenderRun {
  nlohmann::json context;  // scene, mesh sizes, GL renderer, repeats, command line
  std::vector<SorterInfo> sorters;
  int reference = -1;  // index of the first exact-claiming vobench orderer, -1: none
  std::vector<ViewFrames> views;
};

double median(std::vector<double> v);
// Per sorter over the views: views and pixels differing, largest difference, median frame
// and sort seconds, and the median over views of its frame time over VTK's (sorter 0).
nlohmann::json summary(const RenderRun& run);
void write_render_json(const RenderRun& run, const std::string& dir);
void write_render_html(const RenderRun& run, const std::string& dir);

}  // namespace vob
