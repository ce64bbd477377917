// A suite (datasets/suites/*.json, docs/pipeline.md "Suite"): the cartesian product of
// datasets x algorithms x views x image sizes, with repeats, warm-up and what to check,
// plus probes. Example:
//   {"name": "quick",
//    "datasets": [{"name": "gap", "set": {"nx": 8}, "grid": {"gaps": [0, 3]},
//                  "label": "gap {gaps}"}, {"input": "mesh.vtu"}],
//    "algorithms": ["mpvo", {"name": "havs", "grid": {"k": [2, 6]}},  // or ["all"]
//                   {"name": "mine", "command": "./mysort --fast"}],  // external_orderer.h
//    "probes": [{"name": "xmpvo-stability"}],
//    "views": 14, "view_indices": [0, 3] | "spread_views": 3 | "view_directions": [...],
//    "orbit": false,
//    "ortho": false, "zoom": 1, "fit": false, "sizes": ["512x512"], "repeats": 3, "warmup": 1,
//    "threads": 1 | [1, 0], "oracle": true, "supersample": 1, "image_error": true,
//    "image_views": [0], "images_of_violations": false, "exterior_area": true,
//    "vtk_render": {"algorithms": ["xmpvo"], "repeats": 3, "extinction": 1}}
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/vtk_render_entry.h"
#include "harness/geometry/vec3.h"
#include "harness/raster/raster_rule.h"
#include "harness/scene/scene.h"

namespace vob {

struct DatasetSpec {
  std::string name;                          // generator name, or empty with `input`
  std::map<std::string, std::string> set;    // generator parameters
  std::string input;                         // a file instead of a generator
  bool tetrahedralize = false;               // surface input (.off .stl .ply .obj) through TetGen
  std::string variable;                      // Exodus input: the nodal variable read as scalar
  std::string row;                           // the suite's "label" ({key} filled in); may be empty
  std::string label() const;                 // "gap(gaps=3,nx=8)" or the file name
  std::string row_label() const { return row.empty() ? label() : row; }  // a table's row
  nlohmann::json to_json() const;
};

// One grid point of a probe entry: a probe with its parameters, on datasets or on none.
struct ProbeSpec {
  std::string name;                          // registry name (probe.h)
  std::map<std::string, std::string> set;    // parameters
  std::vector<DatasetSpec> datasets;         // empty: the probe runs once, without a scene
  int repeats = 3, warmup = 1;               // the suite's unless the entry overrides
  std::string label() const;                 // "probe:NAME" or "probe:NAME(k=v,...)"
  nlohmann::json parameters() const;         // numbers as numbers
};

// A view from a fixed direction instead of the view set: eye at the bounding-box centre +
// kViewDistance radii along `from` (normalized), looking at the centre, with `up`.
struct ViewDirection {
  Vec3 from, up{0, 0, 1};
};

struct SuiteSpec {
  std::string name;
  std::vector<DatasetSpec> datasets;
  std::vector<std::string> algorithms;  // orderer specs ("havs:k=6"), grids expanded; "all"
  std::vector<ProbeSpec> probes;        // grids expanded
  int views = 14;
  std::vector<int> view_indices;  // empty: all (spread_views fills it)
  std::vector<ViewDirection> view_directions;  // non-empty: these views instead
  bool orbit = false;             // views are the frames of a `views`-frame orbit (view_set.h)
  bool ortho = false;
  double zoom = 1.0;
  bool fit = false;               // each view's window fitted to the box at W*H pixels (fit.h)
  std::vector<std::pair<int, int>> sizes{{512, 512}};
  int repeats = 3, warmup = 1;
  // "interleave": the orderers of a dataset take turns frame by frame on each view (warm-up
  // frames first, in turns too), all prepared at once, so a ratio of two of them is not
  // swayed by the machine changing speed between their jobs (runner.cpp).
  bool interleave = false;
  // TBB parallelism per measurement, each job run once per entry (0: all cores); keys and
  // records carry the count in effect. `--threads N` replaces the list with {N}.
  std::vector<int> threads{0};
  bool oracle = true;
  int supersample = 1;
  RasterRule raster = RasterRule::exact;  // "raster": the oracle's sampling rule (raster_rule.h)
  bool image_error = false;
  std::vector<int> image_views;   // views whose images are written
  bool images_of_violations = false;  // also every view the oracle finds violations in
  bool exterior_area = true;      // Cook et al.'s a per cell record
  // "vtk_render": drawn by vobench-vtk after the suite's records (vtk_render_entry.h).
  std::optional<VtkRenderEntry> vtk_render;
  nlohmann::json source;          // the suite as read (overlays applied): what vobench-vtk is given

  // Validates the whole suite before any work: dataset names and generator parameters
  // (checked without generating), input files present, orderer names and parameters
  // (constructed, not prepared), probe names and parameters (a dry run), views, sizes,
  // repeats. InputError naming `source` and the entry ("quick.json: datasets[1].set: ...").
  // "tiny"/"full" overlays are dropped (the default scale; see scale_overlay.h).
  static SuiteSpec from_json(const nlohmann::json& j, const std::string& source);
  static SuiteSpec load(const std::string& path);
};

// Limits of what a suite or the command line may ask for (documented in --help).
constexpr int kMaxViews = 10000;      // views in a view set or frames of an orbit
constexpr int kMaxRepeats = 1000;     // repeats and warm-up frames per view
constexpr int kMaxImageSide = 16384;  // W and H of an image size
constexpr double kMaxZoom = 100.0;    // view-set zoom factor
constexpr int kMaxThreads = 1024;

// "640x480" -> (640, 480); InputError(where, ...) otherwise.
std::pair<int, int> parse_size(const std::string& s, const std::string& where = "--size");
Scene make_scene(const DatasetSpec& spec);
// The text of a JSON file given to vobench (suite, reproduction): InputError when it cannot
// be read or is not JSON.
nlohmann::json read_json_file(const std::string& path, const std::string& what);

}  // namespace vob
