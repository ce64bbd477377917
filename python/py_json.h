// JSON values (camera dicts, the oracle's counts) between nlohmann::json and Python objects.
#pragma once
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace vob {

pybind11::object json_to_python(const nlohmann::json& j);
// Dicts (string keys), lists, tuples, str, bool, int, float, None; numpy scalars and
// arrays through their Python values. Anything else: InputError naming `what`.
nlohmann::json python_to_json(pybind11::handle h, const std::string& what);

}  // namespace vob
