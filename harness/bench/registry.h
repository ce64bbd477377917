// The registry: the harness knows plugins only through this list. registry.cpp is the one
// file that includes algorithm headers.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "harness/bench/orderer.h"
#include "harness/bench/params.h"

namespace vob {

struct OrdererInfo {
  std::string name;
  SceneKind kind;
  std::string summary;      // one line
  std::string parameters;   // "k=2 (1..8): k-buffer size" ...; empty if none
  std::function<std::unique_ptr<Orderer>(Params&)> make;
};

const std::vector<OrdererInfo>& orderer_registry();
const OrdererInfo& find_orderer(const std::string& name);  // InputError if unknown
// "name:k=v,..." -> a configured orderer (unknown or bad parameters: InputError).
std::unique_ptr<Orderer> make_orderer(const std::string& spec);

}  // namespace vob
