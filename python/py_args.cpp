#include "python/py_args.h"

#include <cstring>
#include <limits>

#include <pybind11/numpy.h>

#include "harness/scene/input_error.h"

namespace py = pybind11;

namespace vob {

namespace {
py::array as_array(py::handle h, const std::string& what) {
  py::array a = py::array::ensure(h);
  if (!a) {
    PyErr_Clear();
    throw InputError(what, py::repr(py::type::handle_of(h)).cast<std::string>(), "is not an array");
  }
  return a;
}

std::vector<int32_t> ids_1d(py::array a, const std::string& what) {
  const py::ssize_t n = a.shape(0);
  std::vector<int32_t> ids(static_cast<size_t>(n));
  if (n == 0) return ids;
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError(what, "dtype " + py::str(a.dtype()).cast<std::string>(), "must be integers");
  if (!py::isinstance<py::array_t<int32_t>>(a)) {
    // Wider or unsigned integers: every id must fit, nothing is wrapped around.
    const py::object lo = py::int_(a.attr("min")()), hi = py::int_(a.attr("max")());
    const py::object bad = lo < py::int_(std::numeric_limits<int32_t>::min())   ? lo
                           : hi > py::int_(std::numeric_limits<int32_t>::max()) ? hi
                                                                                : py::none();
    if (!bad.is_none())
      throw InputError(what, "value " + py::str(bad).cast<std::string>(), "does not fit in int32");
    a = a.attr("astype")("int32");
  }
  const auto v = a.unchecked<int32_t, 1>();
  if (a.strides(0) == static_cast<py::ssize_t>(sizeof(int32_t)))
    std::memcpy(ids.data(), v.data(0), ids.size() * sizeof(int32_t));
  else
    for (py::ssize_t i = 0; i < n; ++i) ids[i] = v(i);
  return ids;
}
}  // namespace

std::vector<int32_t> order_ids(py::handle order) {
  py::array a = as_array(order, "order");
  if (a.ndim() != 1)
    throw InputError("order", "array of " + std::to_string(a.ndim()) + " dimensions", "expected a 1-D array of primitive ids");
  return ids_1d(a, "order");
}

std::vector<int32_t> int32_values(py::handle values, const std::string& what) {
  return ids_1d(as_array(values, what).attr("reshape")(-1), what);
}

std::vector<double> double_values(py::handle values, const std::string& what, int columns) {
  py::array a = as_array(values, what);
  const bool shape_ok = columns ? a.ndim() == 2 && a.shape(1) == columns : a.ndim() == 1;
  if (!shape_ok)
    throw InputError(what, "array of shape " + py::str(py::tuple(a.attr("shape"))).cast<std::string>(),
                     columns ? "expected shape (n, " + std::to_string(columns) + ")" : std::string("expected shape (n,)"));
  const char kind = a.dtype().kind();
  if (a.size() && kind != 'f' && kind != 'i' && kind != 'u')
    throw InputError(what, "dtype " + py::str(a.dtype()).cast<std::string>(), "must be numbers");
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<double>(d.data(), d.data() + d.size());
}

std::string param_text(py::handle value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::str(value).cast<std::string>();
}

}  // namespace vob
