#include "harness/bench/params.h"

#include <cmath>
#include <cstdlib>

#include "harness/bench/names.h"
#include "harness/scene/input_error.h"

namespace vob {

std::pair<std::string, Params> Params::parse_spec(const std::string& spec) {
  const auto colon = spec.find(':');
  std::string name = spec.substr(0, colon);
  Params p(name);
  if (colon != std::string::npos) {
    std::string rest = spec.substr(colon + 1);
    size_t start = 0;
    while (start <= rest.size()) {
      const size_t comma = rest.find(',', start);
      const std::string kv = rest.substr(start, comma == std::string::npos ? std::string::npos
                                                                           : comma - start);
      if (!kv.empty()) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
          throw InputError(name, "parameter '" + kv + "'", "expected key=value");
        p.set(kv.substr(0, eq), kv.substr(eq + 1));
      }
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return {name, p};
}

int Params::get_int(const std::string& key, int def, int lo, int hi) {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end()) return def;
  char* end = nullptr;
  const long v = std::strtol(it->second.c_str(), &end, 10);
  if (it->second.empty() || *end != '\0')
    throw InputError(owner_, "parameter " + key, "'" + it->second + "' is not an integer");
  if (v < lo || v > hi)
    throw InputError(owner_, "parameter " + key, it->second + " is not in [" +
                                                     std::to_string(lo) + ", " +
                                                     std::to_string(hi) + "]");
  return static_cast<int>(v);
}

double Params::get_double(const std::string& key, double def, double lo, double hi) {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end()) return def;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(v))
    throw InputError(owner_, "parameter " + key, "'" + it->second + "' is not a finite number");
  if (v < lo || v > hi)
    throw InputError(owner_, "parameter " + key, it->second + " is not in [" +
                                                     std::to_string(lo) + ", " +
                                                     std::to_string(hi) + "]");
  return v;
}

std::string Params::get_choice(const std::string& key, const std::string& def,
                               const std::set<std::string>& choices) {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end()) return def;
  if (!choices.count(it->second)) {
    std::string all;
    for (const auto& c : choices) all += (all.empty() ? "" : ", ") + c;
    throw InputError(owner_, "parameter " + key, "'" + it->second + "' is not one of " + all);
  }
  return it->second;
}

bool Params::get_bool(const std::string& key, bool def) {
  const std::string v = get_choice(key, def ? "true" : "false", {"true", "false", "1", "0"});
  return v == "true" || v == "1";
}

void Params::check_all_used() const {
  // The keys read are the owner's parameters: they name the known ones in the message.
  for (const auto& [k, v] : values_)
    if (!used_.count(k))
      throw InputError(owner_, "parameter " + k,
                       "is not a known parameter (" +
                           (used_.empty() ? std::string("it takes none")
                                          : known_names_hint(k, {used_.begin(), used_.end()})) +
                           ")");
}

nlohmann::json Params::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : values_) {
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (!v.empty() && *end == '\0' && std::isfinite(d))
      j[k] = (d == std::floor(d) && std::fabs(d) < 1e15) ? nlohmann::json(static_cast<long long>(d))
                                                         : nlohmann::json(d);
    else
      j[k] = v;
  }
  return j;
}

}  // namespace vob
