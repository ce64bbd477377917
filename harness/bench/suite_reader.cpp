#include "harness/bench/suite_reader.h"

#include <cmath>

#include "harness/scene/input_error.h"

namespace vob {

void SuiteReader::fail(const std::string& where, const std::string& why) const {
  throw InputError(source_, where, why);
}

int SuiteReader::integer(const nlohmann::json& v, const std::string& where, int64_t lo, int64_t hi) const {
  const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer()) fail(where, v.dump().substr(0, 40) + " is not " + range);
  // nlohmann keeps non-negative integers unsigned: compare as unsigned first.
  if (v.is_number_unsigned() ? (v.get<uint64_t>() > static_cast<uint64_t>(hi) ||
                                static_cast<int64_t>(v.get<uint64_t>()) < lo)
                             : (v.get<int64_t>() < lo || v.get<int64_t>() > hi))
    fail(where, v.dump() + " is not " + range);
  return static_cast<int>(v.get<int64_t>());
}

double SuiteReader::number(const nlohmann::json& v, const std::string& where, double lo, double hi) const {
  const std::string range = "a number in (" + nlohmann::json(lo).dump() + ", " + nlohmann::json(hi).dump() + "]";
  if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > lo) ||
      !(v.get<double>() <= hi))
    fail(where, v.dump().substr(0, 40) + " is not " + range);
  return v.get<double>();
}

bool SuiteReader::boolean(const nlohmann::json& v, const std::string& where) const {
  if (!v.is_boolean()) fail(where, "must be true or false");
  return v.get<bool>();
}

std::string SuiteReader::string(const nlohmann::json& v, const std::string& where) const {
  if (!v.is_string() || v.get_ref<const std::string&>().empty()) fail(where, "must be a non-empty string");
  return v.get<std::string>();
}

const nlohmann::json& SuiteReader::array(const nlohmann::json& v, const std::string& where) const {
  if (!v.is_array() || v.empty()) fail(where, "must be a non-empty array");
  return v;
}

void SuiteReader::only_keys(const nlohmann::json& v, const std::string& where,
                            const std::set<std::string>& known) const {
  if (!v.is_object()) fail(where, "must be a JSON object");
  for (const auto& [k, _] : v.items())
    if (!known.count(k)) {
      std::string all;
      for (const auto& n : known) all += (all.empty() ? "" : ", ") + n;
      fail(where + (where.empty() ? "" : ".") + k, "is not a known key (known: " + all + ")");
    }
}

std::string SuiteReader::parameter_text(const nlohmann::json& v, const std::string& where) const {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number() || v.is_boolean()) return v.dump();
  fail(where, "must be a number, a string or true/false");
}

std::vector<std::map<std::string, std::string>> SuiteReader::set_and_grid(
    const nlohmann::json& entry, const std::string& where) const {
  std::map<std::string, std::string> base;
  if (entry.contains("set")) {
    if (!entry["set"].is_object()) fail(where + ".set", "must be a JSON object of parameters");
    for (const auto& [k, v] : entry["set"].items()) base[k] = parameter_text(v, where + ".set." + k);
  }
  std::vector<std::map<std::string, std::string>> points{base};
  if (!entry.contains("grid")) return points;
  const auto& grid = entry["grid"];
  if (!grid.is_object() || grid.empty()) fail(where + ".grid", "must be a JSON object of value lists");
  for (const auto& [k, values] : grid.items()) {
    const std::string at = where + ".grid." + k;
    if (base.count(k)) fail(at, "is also in \"set\"");
    array(values, at);
    std::vector<std::map<std::string, std::string>> next;
    for (const auto& p : points)
      for (size_t i = 0; i < values.size(); ++i) {
        auto q = p;
        q[k] = parameter_text(values[i], at + "[" + std::to_string(i) + "]");
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

}  // namespace vob
