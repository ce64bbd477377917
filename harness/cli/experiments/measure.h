// What the paper reproductions share: a named dataset recipe, evenly spread views, and
// one orderer measured over a list of views (mean of the per-view medians, oracle counts).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

// A dataset as a row label, a registry name and generator parameters.
struct Ds {
  std::string label, name;
  std::map<std::string, std::string> set;
};
Scene make(const Ds& d);  // generates it (printing the label to stderr)

// `count` of the 14 Fibonacci views of the scene, evenly spread, at w x h.
std::vector<Camera> views(const Scene& s, int count, int w, int h);

// Mean over views of the per-view median of `repeats` frames after `warmup` frames.
struct AlgoRun {
  bool ran = false;
  double total = 0, prepare = 0, bytes = 0;
  std::map<std::string, double> phases, counters, prepare_phases;
  int views = 0, violating_views = 0;
  int64_t violating_fragments = 0, cycles = 0;
};
AlgoRun run_algo(const std::string& spec, const Scene& scene, const std::vector<Camera>& cams,
                 int warmup, int repeats, bool oracle);

}  // namespace vob
