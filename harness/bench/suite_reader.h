// Reading the values of one suite file: every message names the file and the entry
// ("quick.json: datasets[1].set: ..."); integers are range-checked as 64-bit values before
// they are narrowed. Also the `set` + `grid` expansion shared by datasets, algorithms and
// probes.
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vob {

class SuiteReader {
 public:
  explicit SuiteReader(std::string source) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& where, const std::string& why) const;
  int integer(const nlohmann::json& v, const std::string& where, int64_t lo, int64_t hi) const;
  double number(const nlohmann::json& v, const std::string& where, double lo, double hi) const;
  bool boolean(const nlohmann::json& v, const std::string& where) const;
  std::string string(const nlohmann::json& v, const std::string& where) const;
  const nlohmann::json& array(const nlohmann::json& v, const std::string& where) const;
  void only_keys(const nlohmann::json& v, const std::string& where,
                 const std::set<std::string>& known) const;
  // A parameter value as Params reads it: integers exactly, other numbers as JSON writes
  // them; arrays, objects and null are not parameters.
  std::string parameter_text(const nlohmann::json& v, const std::string& where) const;

  // The entry's "set" merged with each point of its "grid" (the cartesian product of the
  // grid's value lists, first key outermost): one parameter map per point, at least one.
  std::vector<std::map<std::string, std::string>> set_and_grid(const nlohmann::json& entry,
                                                               const std::string& where) const;

 private:
  std::string source_;
};

}  // namespace vob
