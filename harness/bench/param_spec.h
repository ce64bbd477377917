// Parameters declared once: a plugin lists its ParamSpecs in its OrdererInfo, and that one
// list serves parsing ("havs:k=6" is checked against it), documentation (`vobench list`,
// `list --json`) and the record's "parameters" (every declared parameter with its value).
// The plugin reads already-checked values from ResolvedParams and never repeats a default
// or a range.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/params.h"

namespace vob {

struct ParamSpec {
  enum class Kind { Int, Double, Choice, Bool };
  std::string name;
  Kind kind = Kind::Int;
  nlohmann::json def;                // int, double, string or bool, by kind
  double lo = 0, hi = 0;             // Int and Double: inclusive range
  std::vector<std::string> choices;  // Choice
  std::string doc;                   // one line

  static ParamSpec integer(std::string name, int def, int lo, int hi, std::string doc);
  static ParamSpec real(std::string name, double def, double lo, double hi, std::string doc);
  static ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices,
                          std::string doc);
  static ParamSpec boolean(std::string name, bool def, std::string doc);

  // "k=2 (1..16): k-buffer entries per pixel" for `vobench list`.
  std::string describe() const;
  nlohmann::json to_json() const;  // name, kind, default, range or choices, doc
};

const char* param_kind_name(ParamSpec::Kind k);

// Every declared parameter with its value (given, else the default), already checked.
// Asking for an undeclared key or the wrong kind is a programming error (std::logic_error).
class ResolvedParams {
 public:
  int get_int(const std::string& key) const;
  double get_double(const std::string& key) const;
  const std::string& get_choice(const std::string& key) const;
  bool get_bool(const std::string& key) const;
  const nlohmann::json& values() const { return values_; }  // numbers as numbers

 private:
  friend ResolvedParams resolve_params(const std::vector<ParamSpec>&, Params&);
  const nlohmann::json& at(const std::string& key, ParamSpec::Kind kind) const;
  nlohmann::json values_ = nlohmann::json::object();
  std::map<std::string, ParamSpec::Kind> kinds_;
};

// Checks `given` against `specs` (a value that does not parse or is out of range, or a key
// not declared: InputError naming the owner, the key and the reason) and fills defaults.
ResolvedParams resolve_params(const std::vector<ParamSpec>& specs, Params& given);

}  // namespace vob
