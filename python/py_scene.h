// The Python Scene: a scene with the spec it came from and the orderers prepared on it,
// and read-only numpy views of its geometry for sorters written in numpy.
#pragma once
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <pybind11/pybind11.h>

#include "harness/bench/measure.h"
#include "harness/bench/suite.h"

namespace vob {

// Datasets that bring their own views need the spec's name; a second order() at another
// view pays only for the order, as in `vobench check` over its views.
struct PyScene {
  DatasetSpec spec;
  Scene scene;
  // Held with the GIL released: prepared orderers and the scene's lazily derived
  // structures are not safe for two threads at once.
  std::mutex mu;
  std::map<std::string, PreparedOrderer> prepared;
};
using ScenePtr = std::shared_ptr<PyScene>;

// Runs f() on the scene with the GIL released and the scene's mutex held: anything that
// may build a derived structure (faces, centroids, significant voxels) goes through here.
template <typename F>
auto with_scene(PyScene& s, F&& f) {
  pybind11::gil_scoped_release nogil;
  std::lock_guard lock(s.mu);
  return f(s.scene);
}

// Scenes from numpy arrays (copied into the scene, then validated as a file's would be):
// cells as `Scene.cells` gives them (VTK types, offsets [cells+1], connectivity), with
// optional point scalars; triangles as (n, 3) point ids.
ScenePtr cell_scene(pybind11::handle points, pybind11::handle types, pybind11::handle offsets,
                    pybind11::handle connectivity, pybind11::handle scalars);
ScenePtr triangle_scene(pybind11::handle points, pybind11::handle triangles);

// Adds points, cells, triangles, voxel_ids and centroids to the bound Scene class.
void bind_scene_geometry(pybind11::class_<PyScene, ScenePtr>& cls);

}  // namespace vob
