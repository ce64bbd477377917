// Built-in datasets (generators and real data) and file input, all returning a Scene.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct DatasetInfo {
  std::string name;
  SceneKind kind;
  std::string summary;     // one line
  std::string parameters;  // "nx=50 ny=50 nz=100 gaps=0: ..." ; empty if none
  bool hard_case = false;  // part of the hard-case suite
  std::function<Scene(Params&)> make;
  // Hard cases that are about a view (eye in a face plane, eye inside the mesh, faces
  // edge-on in an orthographic view) give their own cameras; null: use the view set.
  std::function<std::vector<Camera>(const Scene&, int width, int height)> views;
};

const std::vector<DatasetInfo>& dataset_registry();
// Generates dataset `name` with `params` (every key must be known, values in range), then
// validates it. Deterministic for its parameters. InputError on anything bad.
Scene make_dataset(const std::string& name, Params params);
const DatasetInfo& find_dataset(const std::string& name);  // InputError if unknown
// Checks dataset `name` and its parameters as make_dataset would (names known, values in
// range, combinations possible) without generating anything. InputError on anything bad.
void check_dataset_params(const std::string& name, Params params);

struct InputOptions {
  bool tetrahedralize = false;  // surfaces (.off .stl .ply .obj): mesh the closed surface
                                // with TetGen (else triangles)
  std::string tetgen_switches;  // extra switches for tetgen (empty: a sensible default)
  std::string variable;         // Exodus: the nodal variable read as scalar (empty: the first)
};
// Reads .vtu/.pvtu/.vtk/.vti (VTK), .node (+ .ele beside it; TetGen), .inr/.inr.gz, .off,
// .stl/.ply/.obj (VTK), .msh (gmsh SDK), .exo/.e (VTK's Exodus II reader). Validates.
Scene load_input(const std::string& path, const InputOptions& opt = {});

// Writes a scene: cells to .vtu or .vtk, triangles to .off, voxels to .vti; atomically
// (temporary file, then rename). InputError for an extension that does not fit the kind.
void write_scene(const Scene& scene, const std::string& path);

}  // namespace vob
