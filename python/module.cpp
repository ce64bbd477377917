// _vobench: the Python face of libvobench.so (package vobench, vobench/__init__.py).
// Scenes from files or generators, the view set of `vobench check`, orderers of the one
// registry, and the oracle; orders are numpy int32 arrays. Bad input raises
// vobench.InputError (a ValueError) with the one line the command line prints.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <sstream>

#include "harness/bench/measure.h"
#include "harness/bench/ordering_check.h"
#include "harness/bench/registry.h"
#include "harness/bench/suite.h"
#include "harness/bench/jobs.h"
#include "datasets/datasets.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/input_error.h"
#include "python/py_args.h"
#include "python/py_json.h"
#include "python/py_scene.h"

namespace py = pybind11;

namespace vob {
namespace {

ScenePtr make_py_scene(DatasetSpec spec) {
  auto s = std::make_shared<PyScene>();
  s->spec = std::move(spec);
  py::gil_scoped_release nogil;
  s->scene = make_scene(s->spec);
  return s;
}

py::tuple vec_tuple(Vec3 v) { return py::make_tuple(v.x, v.y, v.z); }
Vec3 tuple_vec(py::handle h, const char* what) {
  const nlohmann::json j = python_to_json(h, what);
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw InputError("camera", what, "needs 3 numbers");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Camera camera_from_dict(py::handle d) {
  const nlohmann::json j = python_to_json(d, "camera");
  if (!j.is_object()) throw InputError("camera", "value", "expected a dict with the keys of ORDER.json's camera");
  for (const char* k : {"eye", "target", "up", "width", "height"})
    if (!j.contains(k))
      throw InputError("camera", k, "is missing (a camera has eye, target, up, width, height and fov or ortho_height)");
  try {
    return Camera::from_json(j);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("camera", "dict", std::string(e.what()));
  }
}

std::string camera_repr(const Camera& c) { return "vobench.Camera(" + c.to_json().dump() + ")"; }

// An array owning the vector: numpy reads the vector's buffer, the capsule frees it.
template <typename T>
py::array owned_array(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, heap->data(), owner);
}

// The camera is copied before the GIL is released: Python may change the object meanwhile.
py::object order(PyScene& s, const Camera cam, const std::string& algorithm, bool details) {
  FrameMeasurement m;
  double prepare_seconds = 0;
  {
    py::gil_scoped_release nogil;
    std::lock_guard lock(s.mu);
    cam.validate();
    auto it = s.prepared.find(algorithm);
    if (it == s.prepared.end()) it = s.prepared.emplace(algorithm, prepare_orderer(algorithm, s.scene)).first;
    prepare_seconds = it->second.prepare_seconds;
    m = measure_frame(it->second, cam, 0, 1);
    check_complete(s.scene, m.ordering, algorithm);
  }
  const py::ssize_t n = py::ssize_t(m.ordering.order.size());
  py::array ids = owned_array(std::move(m.ordering.order), {n});
  if (!details) return ids;
  py::dict info;
  info["seconds"] = m.total_median();  // as `vobench check --json` reports per view
  info["phases"] = json_to_python(m.phases_json());
  info["prepare_seconds"] = prepare_seconds;
  info["cycles"] = m.ordering.cycles.cycles;
  info["counters"] = json_to_python(m.ordering.counters);
  return py::make_tuple(ids, info);
}

py::dict check(PyScene& s, const Camera cam, py::handle order_obj, int supersample, bool violation_mask) {
  if (supersample < 1 || supersample > 16)
    throw InputError("check", "supersample " + std::to_string(supersample), "must be in [1, 16]");
  Ordering ordering;
  ordering.order = order_ids(order_obj);
  OracleResult r;
  {
    py::gil_scoped_release nogil;
    std::lock_guard lock(s.mu);
    cam.validate();
    try {
      check_complete(s.scene, ordering, "order");
    } catch (const std::logic_error& e) {
      throw InputError(e.what());  // an order given here is input, not an orderer's bug
    }
    OracleOptions opt;
    opt.supersample = supersample;
    opt.violation_mask = violation_mask;
    r = check_ordering(s.scene, cam, ordering.order, opt);
  }
  nlohmann::json j = r.to_json();
  j["judged"] = "order";  // the key `vobench check --json` gives every verdict
  py::dict out = json_to_python(j);
  if (violation_mask)
    out["violation_mask"] = owned_array(std::move(r.violation_mask), {r.mask_height, r.mask_width});
  return out;
}

py::list views(PyScene& s, py::object n, int width, int height, bool ortho, double zoom) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw InputError("views", std::to_string(width) + "x" + std::to_string(height),
                     "expected 1 <= width, height <= " + std::to_string(kMaxImageSide));
  if (!(zoom > 0 && zoom <= kMaxZoom))
    throw InputError("views", "zoom " + short_number(zoom), "must be in (0, " + short_number(kMaxZoom) + "]");
  const bool own = s.spec.input.empty() && find_dataset(s.spec.name).views;
  if (own && !n.is_none())
    throw InputError("views", s.spec.name, "this dataset brings its own views; call views(scene) without n");
  const int count = n.is_none() ? 14 : n.cast<int>();
  if (count < 1 || count > kMaxViews)
    throw InputError("views", "n " + std::to_string(count), "must be in [1, " + std::to_string(kMaxViews) + "]");
  auto cams = with_scene(s, [&](const Scene& sc) {
    auto v = dataset_views(s.spec, sc, count, {}, width, height, ortho, zoom);
    for (auto& [i, cam] : v) cam.validate();
    return v;
  });
  py::list out;
  for (auto& [i, cam] : cams) out.append(py::cast(cam));
  return out;
}

size_t primitives(PyScene& s) {
  return with_scene(s, [](const Scene& sc) { return sc.num_primitives(); });  // voxels: derived
}

std::string scene_repr(PyScene& s) {
  std::ostringstream o;
  o << "vobench.Scene(" << s.spec.label() << ", " << scene_kind_name(s.scene.kind()) << ", "
    << primitives(s) << " primitives)";
  return o.str();
}

}  // namespace
}  // namespace vob

PYBIND11_MODULE(_vobench, m) {
  using namespace vob;
  m.doc() = "vobench: visibility orderings of meshes, judged by the z-buffer oracle";
  // InputError -> vobench.InputError, a ValueError carrying the command line's one line.
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PyScene, ScenePtr> scene(m, "Scene", "a mesh (cells), triangle soup or voxel grid");
  scene.def_property_readonly("kind", [](const PyScene& s) { return scene_kind_name(s.scene.kind()); })
      .def_property_readonly("num_primitives", &primitives)
      .def_property_readonly("bounds", [](const PyScene& s) {
        const Aabb b = s.scene.bounds();
        return py::make_tuple(vec_tuple(b.lo), vec_tuple(b.hi));
      })
      .def_property_readonly("label", [](const PyScene& s) { return s.spec.label(); })
      .def("__len__", &primitives)
      .def_property_readonly("prepared", [](PyScene& s) {
        return with_scene(s, [&](const Scene&) {
          std::vector<std::string> names;
          for (const auto& [spec, p] : s.prepared) names.push_back(spec);
          return names;
        });
      }, "the orderers prepared on this scene by order() (kept for the next view)")
      .def("release_orderers", [](PyScene& s) { with_scene(s, [&](const Scene&) { s.prepared.clear(); }); },
           "frees the prepared orderers (order() prepares again)")
      .def("__repr__", &scene_repr);
  bind_scene_geometry(scene);

  py::class_<Camera>(m, "Camera", "a view: the camera keys of ORDER.json")
      .def(py::init([](py::handle eye, py::handle target, py::handle up, double fov, py::object ortho_height,
                       int width, int height) {
             Camera c;
             c.eye = tuple_vec(eye, "eye");
             c.target = tuple_vec(target, "target");
             c.up = tuple_vec(up, "up");
             c.fov_deg = fov;
             c.ortho = !ortho_height.is_none();
             if (c.ortho) c.ortho_height = ortho_height.cast<double>();
             c.width = width;
             c.height = height;
             c.validate();
             return c;
           }),
           py::kw_only(), py::arg("eye") = py::make_tuple(0, 0, 5), py::arg("target") = py::make_tuple(0, 0, 0),
           py::arg("up") = py::make_tuple(0, 1, 0), py::arg("fov") = 40.0, py::arg("ortho_height") = py::none(),
           py::arg("width") = 512, py::arg("height") = 512)
      .def_property("eye", [](const Camera& c) { return vec_tuple(c.eye); },
                    [](Camera& c, py::handle v) { c.eye = tuple_vec(v, "eye"); })
      .def_property("target", [](const Camera& c) { return vec_tuple(c.target); },
                    [](Camera& c, py::handle v) { c.target = tuple_vec(v, "target"); })
      .def_property("up", [](const Camera& c) { return vec_tuple(c.up); },
                    [](Camera& c, py::handle v) { c.up = tuple_vec(v, "up"); })
      .def_readwrite("ortho", &Camera::ortho)
      .def_readwrite("fov", &Camera::fov_deg)
      .def_readwrite("ortho_height", &Camera::ortho_height)
      .def_readwrite("width", &Camera::width)
      .def_readwrite("height", &Camera::height)
      .def("to_dict", [](const Camera& c) { return json_to_python(c.to_json()); })
      .def_static("from_dict", &camera_from_dict, py::arg("d"))
      .def(py::pickle([](const Camera& c) { return py::str(c.to_json().dump()); },
                      [](const py::str& s) { return Camera::from_json(nlohmann::json::parse(s.cast<std::string>())); }))
      .def("__eq__", [](const Camera& a, const Camera& b) { return a.to_json() == b.to_json(); })
      .def("__repr__", &camera_repr);

  m.def("load", [](const std::string& path, bool tetrahedralize) {
          DatasetSpec spec;
          spec.input = path;
          spec.tetrahedralize = tetrahedralize;
          return make_py_scene(spec);
        },
        py::arg("path"), py::arg("tetrahedralize") = false,
        "read a mesh or volume file (.vtu .vtk .vti .node .inr .off; as `vobench --input`)");
  m.def("generate", [](const std::string& name, py::kwargs params) {
          DatasetSpec spec;
          spec.name = name;
          for (const auto& [k, v] : params) spec.set[k.cast<std::string>()] = param_text(v);
          return make_py_scene(spec);
        },
        py::arg("name"), "a built-in dataset (`vobench generate --dataset NAME --set k=v`)");
  m.def("cell_mesh", &cell_scene, py::arg("points"), py::arg("types"), py::arg("offsets"),
        py::arg("connectivity"), py::arg("scalars") = py::none(),
        "a cell scene from arrays, as Scene.cells gives them (copied, then validated)");
  m.def("triangle_soup", &triangle_scene, py::arg("points"), py::arg("triangles"),
        "a triangle scene from (n, 3) points and (m, 3) point ids (copied, then validated)");
  m.def("views", &views, py::arg("scene"), py::arg("n") = py::none(), py::arg("width") = 512,
        py::arg("height") = 512, py::kw_only(), py::arg("ortho") = false, py::arg("zoom") = 1.0,
        "the view set of `vobench check --views n --size WxH` (its own views for hard cases)");
  m.def("order", &order, py::arg("scene"), py::arg("camera"), py::arg("algorithm"), py::kw_only(),
        py::arg("details") = false,
        "back-to-front primitive ids (numpy int32, no copy); details=True: (ids, timings)");
  m.def("check", &check, py::arg("scene"), py::arg("camera"), py::arg("order"), py::kw_only(),
        py::arg("supersample") = 1, py::arg("violation_mask") = false,
        "the oracle's counts for an order at a view (the keys of `vobench check --json`)");
  m.def("algorithms", [](py::object kind) {
          py::list out;
          for (const OrdererInfo& i : orderer_registry())
            if (kind.is_none() || kind.cast<std::string>() == scene_kind_name(i.kind)) out.append(i.name);
          return out;
        },
        py::arg("kind") = py::none(), "registered orderer names (of one scene kind)");
  m.def("datasets", []() {
    py::list out;
    for (const DatasetInfo& d : dataset_registry()) out.append(d.name);
    return out;
  }, "built-in dataset names");
}
