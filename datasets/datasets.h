// Built-in datasets (generators and real data) and file input, all returning a Scene.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

struct DatasetInfo {
  std::string name;
  SceneKind kind;
  std::string summary;     // one line
  std::string parameters;  // "nx=50 ny=50 nz=100 gaps=0: ..." ; empty if none
  bool hard_case = false;  // part of the hard-case suite
  std::function<Scene(Params&)> make;
};

const std::vector<DatasetInfo>& dataset_registry();
// Generates dataset `name` with `params` (every key must be known, values in range), then
// validates it. Deterministic for its parameters. InputError on anything bad.
Scene make_dataset(const std::string& name, Params params);

struct InputOptions {
  bool tetrahedralize = false;  // .off: mesh the closed surface with TetGen (else triangles)
  std::string tetgen_switches;  // extra switches for tetgen (empty: a sensible default)
};
// Reads .vtu/.vtk/.vti (VTK), .node (+ .ele beside it; TetGen), .inr, .off. Validates.
Scene load_input(const std::string& path, const InputOptions& opt = {});

}  // namespace vob
