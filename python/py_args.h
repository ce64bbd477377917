// Python arguments into the harness's types: orders and other id arrays, coordinates, and
// generator parameters given as keyword arguments. Nothing is wrapped around or truncated:
// a value that does not fit is an InputError (-> ValueError) naming the argument.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace vob {

// A 1-D array of primitive ids: an int32 numpy array is read in place (one copy, into the
// vector the oracle takes); other integer arrays and sequences are converted when every id
// fits in int32. InputError (-> ValueError) for other shapes, dtypes or values.
std::vector<int32_t> order_ids(pybind11::handle order);
// The same for any integer array flattened (triangles (n, 3), connectivity, offsets);
// `what` names it in messages.
std::vector<int32_t> int32_values(pybind11::handle values, const std::string& what);
// A float array of shape (n, 3) (or (n,) with `columns` 0) as doubles; InputError else.
std::vector<double> double_values(pybind11::handle values, const std::string& what, int columns);

// A keyword value as `--set k=v` text: True/False -> true/false, numbers and strings as
// str() writes them (1e-06, 8, 'helix').
std::string param_text(pybind11::handle value);

}  // namespace vob
