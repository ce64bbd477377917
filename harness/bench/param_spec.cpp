#include "harness/bench/param_spec.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace vob {

namespace {
std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}
}  // namespace

const char* param_kind_name(ParamSpec::Kind k) {
  switch (k) {
    case ParamSpec::Kind::Int: return "int";
    case ParamSpec::Kind::Double: return "double";
    case ParamSpec::Kind::Choice: return "choice";
    case ParamSpec::Kind::Bool: return "bool";
  }
  return "?";
}

ParamSpec ParamSpec::integer(std::string name, int def, int lo, int hi, std::string doc) {
  if (def < lo || def > hi) throw std::logic_error("parameter " + name + ": default out of range");
  ParamSpec s{std::move(name), Kind::Int, def, double(lo), double(hi), {}, std::move(doc)};
  return s;
}

ParamSpec ParamSpec::real(std::string name, double def, double lo, double hi, std::string doc) {
  if (!(def >= lo && def <= hi)) throw std::logic_error("parameter " + name + ": default out of range");
  return {std::move(name), Kind::Double, def, lo, hi, {}, std::move(doc)};
}

ParamSpec ParamSpec::choice(std::string name, std::string def, std::vector<std::string> choices,
                            std::string doc) {
  if (std::find(choices.begin(), choices.end(), def) == choices.end())
    throw std::logic_error("parameter " + name + ": default is not a choice");
  return {std::move(name), Kind::Choice, def, 0, 0, std::move(choices), std::move(doc)};
}

ParamSpec ParamSpec::boolean(std::string name, bool def, std::string doc) {
  return {std::move(name), Kind::Bool, def, 0, 0, {"true", "false"}, std::move(doc)};
}

std::string ParamSpec::describe() const {
  std::string s = name + "=";
  switch (kind) {
    case Kind::Int: s += std::to_string(def.get<int>()) + " (" + number_text(lo) + ".." + number_text(hi) + ")"; break;
    case Kind::Double: s += number_text(def.get<double>()) + " (" + number_text(lo) + ".." + number_text(hi) + ")"; break;
    case Kind::Bool: s += def.get<bool>() ? "true (true|false)" : "false (true|false)"; break;
    case Kind::Choice: {
      s += def.get<std::string>() + " (";
      for (size_t i = 0; i < choices.size(); ++i) s += (i ? "|" : "") + choices[i];
      s += ")";
      break;
    }
  }
  return s + ": " + doc;
}

nlohmann::json ParamSpec::to_json() const {
  nlohmann::json j{{"name", name}, {"kind", param_kind_name(kind)}, {"default", def}, {"doc", doc}};
  if (kind == Kind::Int) j["range"] = {static_cast<long long>(lo), static_cast<long long>(hi)};
  if (kind == Kind::Double) j["range"] = {lo, hi};
  if (kind == Kind::Choice || kind == Kind::Bool) j["choices"] = choices;
  return j;
}

const nlohmann::json& ResolvedParams::at(const std::string& key, ParamSpec::Kind kind) const {
  auto it = kinds_.find(key);
  if (it == kinds_.end()) throw std::logic_error("parameter " + key + " is not declared");
  if (it->second != kind)
    throw std::logic_error("parameter " + key + " is declared " + param_kind_name(it->second) +
                           ", read as " + param_kind_name(kind));
  return values_.at(key);
}

int ResolvedParams::get_int(const std::string& key) const { return at(key, ParamSpec::Kind::Int).get<int>(); }
double ResolvedParams::get_double(const std::string& key) const {
  return at(key, ParamSpec::Kind::Double).get<double>();
}
const std::string& ResolvedParams::get_choice(const std::string& key) const {
  return at(key, ParamSpec::Kind::Choice).get_ref<const std::string&>();
}
bool ResolvedParams::get_bool(const std::string& key) const { return at(key, ParamSpec::Kind::Bool).get<bool>(); }

ResolvedParams resolve_params(const std::vector<ParamSpec>& specs, Params& given) {
  ResolvedParams r;
  for (const ParamSpec& s : specs) {
    r.kinds_[s.name] = s.kind;
    switch (s.kind) {
      case ParamSpec::Kind::Int:
        r.values_[s.name] = given.get_int(s.name, s.def.get<int>(), int(s.lo), int(s.hi));
        break;
      case ParamSpec::Kind::Double:
        r.values_[s.name] = given.get_double(s.name, s.def.get<double>(), s.lo, s.hi);
        break;
      case ParamSpec::Kind::Choice:
        r.values_[s.name] = given.get_choice(s.name, s.def.get<std::string>(),
                                             std::set<std::string>(s.choices.begin(), s.choices.end()));
        break;
      case ParamSpec::Kind::Bool: r.values_[s.name] = given.get_bool(s.name, s.def.get<bool>()); break;
    }
  }
  given.check_all_used();
  return r;
}

}  // namespace vob
