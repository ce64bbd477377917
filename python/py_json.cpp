#include "python/py_json.h"

#include "harness/scene/input_error.h"

namespace py = pybind11;

namespace vob {

py::object json_to_python(const nlohmann::json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null: return py::none();
    case T::boolean: return py::bool_(j.get<bool>());
    case T::number_integer: return py::int_(j.get<int64_t>());
    case T::number_unsigned: return py::int_(j.get<uint64_t>());
    case T::number_float: return py::float_(j.get<double>());
    case T::string: return py::str(j.get<std::string>());
    case T::array: {
      py::list out;
      for (const auto& v : j) out.append(json_to_python(v));
      return out;
    }
    case T::object: {
      py::dict out;
      for (const auto& [k, v] : j.items()) out[py::str(k)] = json_to_python(v);
      return out;
    }
    default: throw InputError("json", "value", "has a type Python cannot hold");
  }
}

nlohmann::json python_to_json(py::handle h, const std::string& what) {
  if (h.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(h)) return h.cast<bool>();
  if (py::isinstance<py::int_>(h)) return h.cast<int64_t>();
  if (py::isinstance<py::float_>(h)) return h.cast<double>();
  if (py::isinstance<py::str>(h)) return h.cast<std::string>();
  if (py::isinstance<py::dict>(h)) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [k, v] : h.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k)) throw InputError(what, "key " + py::repr(k).cast<std::string>(), "is not a string");
      const std::string key = k.cast<std::string>();
      out[key] = python_to_json(v, what + "." + key);
    }
    return out;
  }
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& v : h) out.push_back(python_to_json(v, what));
    return out;
  }
  // numpy scalars and arrays: their plain Python values (np.float64(1.0) -> 1.0).
  if (py::hasattr(h, "tolist")) return python_to_json(h.attr("tolist")(), what);
  throw InputError(what, py::repr(h).cast<std::string>(), "is not a JSON value (dict, list, str, number, bool, None)");
}

}  // namespace vob
