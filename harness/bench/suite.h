// A suite (datasets/suites/*.json): the cartesian product of datasets x algorithms x views x
// image sizes, with repeats, warm-up and what to check. Example:
//   {"name": "quick",
//    "datasets": [{"name": "gap", "set": {"nx": 8, "gaps": 3}}, {"input": "mesh.vtu"}],
//    "algorithms": ["mpvo", "centroid:key=view"],   // or ["all"]: every orderer of the kind
//    "views": 14, "view_indices": [0, 3], "ortho": false, "zoom": 1,
//    "sizes": ["512x512", "640x480"], "repeats": 3, "warmup": 1,
//    "oracle": true, "supersample": 1, "image_error": true, "image_views": [0],
//    "images_of_violations": false}
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/scene.h"

namespace vob {

struct DatasetSpec {
  std::string name;                          // generator name, or empty with `input`
  std::map<std::string, std::string> set;    // generator parameters
  std::string input;                         // a file instead of a generator
  bool tetrahedralize = false;               // .off input through TetGen
  std::string label() const;                 // "gap(gaps=3,nx=8)" or the file name
  nlohmann::json to_json() const;
};

struct SuiteSpec {
  std::string name;
  std::vector<DatasetSpec> datasets;
  std::vector<std::string> algorithms;
  int views = 14;
  std::vector<int> view_indices;  // empty: all
  bool ortho = false;
  double zoom = 1.0;
  std::vector<std::pair<int, int>> sizes{{512, 512}};
  int repeats = 3, warmup = 1;
  bool oracle = true;
  int supersample = 1;
  bool image_error = false;
  std::vector<int> image_views;   // views whose images are written
  bool images_of_violations = false;  // also every view the oracle finds violations in

  // Validates the whole suite before any work: dataset names and generator parameters
  // (checked without generating), input files present, orderer names and parameters
  // (constructed, not prepared), views, sizes, repeats. InputError naming `source` and the
  // entry ("quick.json: datasets[1].set: ...").
  static SuiteSpec from_json(const nlohmann::json& j, const std::string& source);
  static SuiteSpec load(const std::string& path);
};

// Limits of what a suite or the command line may ask for (documented in --help).
constexpr int kMaxViews = 10000;      // views in a view set or frames of an orbit
constexpr int kMaxRepeats = 1000;     // repeats and warm-up frames per view
constexpr int kMaxImageSide = 16384;  // W and H of an image size
constexpr double kMaxZoom = 100.0;    // view-set zoom factor

// "640x480" -> (640, 480); InputError(where, ...) otherwise.
std::pair<int, int> parse_size(const std::string& s, const std::string& where = "--size");
Scene make_scene(const DatasetSpec& spec);

}  // namespace vob
