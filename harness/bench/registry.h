// The registry: the harness knows plugins only through this list. registry.cpp is the one
// file that includes algorithm headers. Each plugin's OrdererInfo (name, scene kind,
// summary, parameters) is written once, in the plugin's own folder.
#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/orderer.h"
#include "harness/bench/param_spec.h"

namespace vob {

struct OrdererInfo {
  std::string name;
  SceneKind kind;
  std::string summary;            // one line
  std::vector<ParamSpec> params;  // declared once: parsing, `vobench list`, records
  std::function<std::unique_ptr<Orderer>(const ResolvedParams&)> make;
};

// An orderer from its registration and given parameters, checked against the declared
// specs (for probes in plugin folders, which build their own orderers' variants).
inline std::unique_ptr<Orderer> make_from_info(const OrdererInfo& info, Params& given) {
  return info.make(resolve_params(info.params, given));
}

// Built-in orderers first, then those registered at run time (plugins loaded with --plugin,
// external commands from suites). A deque: references to entries stay valid as it grows.
const std::deque<OrdererInfo>& orderer_registry();
// Adds an orderer (a plugin's or an external command's). InputError when the name is taken
// or is not a plain name (letters, digits, '_', '-', '.').
void register_orderer(OrdererInfo info);
const OrdererInfo& find_orderer(const std::string& name);  // InputError if unknown
// The info of the orderer a spec "name:k=v,..." names (InputError if unknown).
const OrdererInfo& spec_orderer(const std::string& spec);
// "name:k=v,..." checked against the declared parameters (unknown orderer or key, a value
// that does not parse or is out of range: InputError naming orderer, key and reason).
ResolvedParams resolve_orderer_params(const std::string& spec);
// "name:k=v,..." -> a configured orderer (unknown or bad parameters: InputError).
std::unique_ptr<Orderer> make_orderer(const std::string& spec);
// Every declared parameter of the spec's orderer with its effective value, numbers as
// numbers: the record's "parameters".
nlohmann::json resolved_parameters(const std::string& spec);

}  // namespace vob
