#include "python/py_scene.h"

#include <pybind11/numpy.h>

#include "harness/scene/cell_types.h"
#include "harness/scene/input_error.h"
#include "python/py_args.h"

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
    const std::vector<Vec3>& c = *with_scene(s, [](const Scene& sc) { return &sc.cell_centroids().points; });
    return points_view(self, c);
  }
  std::vector<Vec3> out;
  if (s.scene.kind() == SceneKind::Triangles) {
    const TriangleSoup& t = s.scene.soup();
    out.reserve(t.tris.size());
    for (const auto& tri : t.tris)
      out.push_back((t.points[tri[0]] + t.points[tri[1]] + t.points[tri[2]]) * (1.0 / 3.0));
  } else {
    const std::vector<int32_t>* ids = with_scene(s, [](const Scene& sc) { return &sc.significant_voxels(); });
    out.reserve(ids->size());
    for (int32_t id : *ids) out.push_back(s.scene.grid().centre_of(id));
  }
  py::array_t<double> a({py::ssize_t(out.size()), py::ssize_t(3)});
  if (!out.empty()) std::memcpy(a.mutable_data(), &out[0].x, out.size() * sizeof(Vec3));
  return a;
}

// Array scenes are named "arrays" in messages and labels; views() gives them the Fibonacci set.
constexpr const char* kArrays = "arrays";

std::vector<Vec3> vec3s(const std::vector<double>& xyz) {
  std::vector<Vec3> out(xyz.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  return out;
}

ScenePtr wrap(Scene scene) {
  auto s = std::make_shared<PyScene>();
  s->spec.input = kArrays;
  s->scene = std::move(scene);
  return s;
}
}  // namespace

ScenePtr cell_scene(py::handle points, py::handle types, py::handle offsets, py::handle connectivity,
                    py::handle scalars) {
  CellMesh m;
  m.points = vec3s(double_values(points, "points", 3));
  const std::vector<int32_t> t = int32_values(types, "types");
  m.offsets = int32_values(offsets, "offsets");
  m.conn = int32_values(connectivity, "connectivity");
  if (!scalars.is_none()) m.scalars = double_values(scalars, "scalars", 0);
  // What validate_cell_mesh takes for granted: offsets that index the connectivity.
  if (m.offsets.size() != t.size() + 1)
    throw InputError(kArrays, "offsets", "expected " + std::to_string(t.size() + 1) + " (cells + 1), got " +
                                             std::to_string(m.offsets.size()));
  if (m.offsets.front() != 0 || m.offsets.back() != int64_t(m.conn.size()))
    throw InputError(kArrays, "offsets", "must start at 0 and end at the connectivity's length " +
                                             std::to_string(m.conn.size()));
  for (size_t c = 0; c < t.size(); ++c) {
    if (m.offsets[c + 1] < m.offsets[c])
      throw InputError(kArrays, "offsets", "decrease at cell " + std::to_string(c));
    if (!is_supported_cell_code(t[c]))
      throw InputError(kArrays, "cell " + std::to_string(c), "unsupported cell type " + std::to_string(t[c]));
    m.types.push_back(static_cast<CellType>(t[c]));
  }
  ScenePtr s;
  {
    py::gil_scoped_release nogil;
    validate_cell_mesh(m, kArrays);
    s = wrap(Scene::from_mesh(kArrays, std::move(m)));
    s->scene.faces();  // as a loaded file: a face shared by three cells is refused here
  }
  return s;
}

ScenePtr triangle_scene(py::handle points, py::handle triangles) {
  TriangleSoup soup;
  soup.points = vec3s(double_values(points, "points", 3));
  const py::array tris = py::array::ensure(triangles);
  if (!tris || tris.ndim() != 2 || tris.shape(1) != 3) {
    PyErr_Clear();
    throw InputError(kArrays, "triangles", "expected an integer array of shape (n, 3)");
  }
  const std::vector<int32_t> ids = int32_values(tris, "triangles");
  for (size_t i = 0; i + 2 < ids.size(); i += 3) soup.tris.push_back({ids[i], ids[i + 1], ids[i + 2]});
  py::gil_scoped_release nogil;
  validate_triangle_soup(soup, kArrays);
  return wrap(Scene::from_soup(kArrays, std::move(soup)));
}

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
        const std::vector<int32_t>* ids = with_scene(s, [](const Scene& sc) { return &sc.significant_voxels(); });
        return view(self, ids->data(), {py::ssize_t(ids->size())});
      }, "the significant voxels' ids (the primitives an order lists), int32, read-only")
      .def_property_readonly("centroids", &centroids,
                             "(primitives, 3) float64 centres in primitive order (voxels: of voxel_ids)");
}

}  // namespace vob
