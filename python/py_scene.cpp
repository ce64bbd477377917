#include "python/py_scene.h"

#include <pybind11/numpy.h>

#include "harness/scene/input_error.h"

namespace py = pybind11;

namespace vob {

namespace {
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are read as (n, 3) doubles");

// A read-only array over the scene's own memory, keeping the Python Scene alive. The
// scene's primitive data is immutable (shared, const), so numpy may look but not write.
template <typename T>
py::array view(py::handle owner, const T* data, std::vector<py::ssize_t> shape) {
  py::array a(py::dtype::of<T>(), std::move(shape), data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}
py::array points_view(py::handle owner, const std::vector<Vec3>& p) {
  return view(owner, p.empty() ? nullptr : &p[0].x, {py::ssize_t(p.size()), 3});
}

const PyScene& of_kind(py::handle self, SceneKind kind, const char* what) {
  const PyScene& s = self.cast<const PyScene&>();
  if (s.scene.kind() != kind)
    throw InputError("scene", what, std::string("applies to ") + scene_kind_name(kind) + ", this scene has " +
                                        scene_kind_name(s.scene.kind()));
  return s;
}

// Primitive centres in primitive order (voxels: in the order of voxel_ids). Cells: the
// scene's own cached centroids (no copy); triangles and voxels: computed here.
py::array centroids(py::handle self) {
  PyScene& s = self.cast<PyScene&>();
  if (s.scene.kind() == SceneKind::Cells) {
    const std::vector<Vec3>* c = nullptr;
    {
      py::gil_scoped_release nogil;
      std::lock_guard lock(s.mu);
      c = &s.scene.cell_centroids().points;
    }
    return points_view(self, *c);
  }
  std::vector<Vec3> out;
  if (s.scene.kind() == SceneKind::Triangles) {
    const TriangleSoup& t = s.scene.soup();
    out.reserve(t.tris.size());
    for (const auto& tri : t.tris)
      out.push_back((t.points[tri[0]] + t.points[tri[1]] + t.points[tri[2]]) * (1.0 / 3.0));
  } else {
    const std::vector<int32_t>* ids = nullptr;
    {
      py::gil_scoped_release nogil;
      std::lock_guard lock(s.mu);
      ids = &s.scene.significant_voxels();
    }
    out.reserve(ids->size());
    for (int32_t id : *ids) out.push_back(s.scene.grid().centre_of(id));
  }
  py::array_t<double> a({py::ssize_t(out.size()), py::ssize_t(3)});
  if (!out.empty()) std::memcpy(a.mutable_data(), &out[0].x, out.size() * sizeof(Vec3));
  return a;
}
}  // namespace

void bind_scene_geometry(py::class_<PyScene, ScenePtr>& cls) {
  cls.def_property_readonly("points", [](py::handle self) {
       const PyScene& s = self.cast<const PyScene&>();
       if (s.scene.kind() == SceneKind::Voxels)
         throw InputError("scene", "points", "applies to cells and triangles; voxels have centroids");
       return points_view(self, s.scene.kind() == SceneKind::Cells ? s.scene.mesh().points : s.scene.soup().points);
     }, "(points, 3) float64, read-only")
      .def_property_readonly("cells", [](py::handle self) {
        const CellMesh& m = of_kind(self, SceneKind::Cells, "cells").scene.mesh();
        static_assert(sizeof(CellType) == 1, "cell types are read as uint8");
        return py::make_tuple(view(self, reinterpret_cast<const uint8_t*>(m.types.data()), {py::ssize_t(m.types.size())}),
                              view(self, m.offsets.data(), {py::ssize_t(m.offsets.size())}),
                              view(self, m.conn.data(), {py::ssize_t(m.conn.size())}));
      }, "(VTK types uint8, offsets int32 [cells+1], connectivity int32), read-only")
      .def_property_readonly("triangles", [](py::handle self) {
        const TriangleSoup& t = of_kind(self, SceneKind::Triangles, "triangles").scene.soup();
        return view(self, t.tris.empty() ? nullptr : t.tris[0].data(), {py::ssize_t(t.tris.size()), 3});
      }, "(triangles, 3) int32 point ids, read-only")
      .def_property_readonly("voxel_ids", [](py::handle self) {
        PyScene& s = const_cast<PyScene&>(of_kind(self, SceneKind::Voxels, "voxel_ids"));
        const std::vector<int32_t>* ids = nullptr;
        {
          py::gil_scoped_release nogil;
          std::lock_guard lock(s.mu);
          ids = &s.scene.significant_voxels();
        }
        return view(self, ids->data(), {py::ssize_t(ids->size())});
      }, "the significant voxels' ids (the primitives an order lists), int32, read-only")
      .def_property_readonly("centroids", &centroids,
                             "(primitives, 3) float64 centres in primitive order (voxels: of voxel_ids)");
}

}  // namespace vob
