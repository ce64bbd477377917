#include "python/py_args.h"

#include <cstring>
#include <limits>

#include <pybind11/numpy.h>

#include "harness/scene/input_error.h"

namespace py = pybind11;

namespace vob {

std::vector<int32_t> order_ids(py::handle order) {
  py::array a = py::array::ensure(order);
  if (!a) {
    PyErr_Clear();
    throw InputError("order", py::repr(py::type::handle_of(order)).cast<std::string>(), "is not an array of primitive ids");
  }
  if (a.ndim() != 1)
    throw InputError("order", "array of " + std::to_string(a.ndim()) + " dimensions", "expected a 1-D array of primitive ids");
  const py::ssize_t n = a.shape(0);
  std::vector<int32_t> ids(static_cast<size_t>(n));
  if (n == 0) return ids;
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError("order", "dtype " + py::str(a.dtype()).cast<std::string>(), "primitive ids must be integers");
  if (!py::isinstance<py::array_t<int32_t>>(a)) {
    // Wider or unsigned integers: every id must fit, nothing is wrapped around.
    const py::object lo = py::int_(a.attr("min")()), hi = py::int_(a.attr("max")());
    const py::object bad = lo < py::int_(std::numeric_limits<int32_t>::min())   ? lo
                           : hi > py::int_(std::numeric_limits<int32_t>::max()) ? hi
                                                                                : py::none();
    if (!bad.is_none())
      throw InputError("order", "id " + py::str(bad).cast<std::string>(), "does not fit in int32");
    a = a.attr("astype")("int32");
  }
  const auto v = a.unchecked<int32_t, 1>();
  if (a.strides(0) == static_cast<py::ssize_t>(sizeof(int32_t)))
    std::memcpy(ids.data(), v.data(0), ids.size() * sizeof(int32_t));
  else
    for (py::ssize_t i = 0; i < n; ++i) ids[i] = v(i);
  return ids;
}

std::string param_text(py::handle value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::str(value).cast<std::string>();
}

}  // namespace vob
