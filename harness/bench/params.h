// Params: key=value settings of an orderer ("havs:k=6") or a generator (--set nx=10).
// Every key must be consumed: an unknown key or a value that does not parse is an
// InputError naming the owner, the key and the reason.
#pragma once
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace vob {

class Params {
 public:
  Params() = default;
  explicit Params(std::string owner) : owner_(std::move(owner)) {}
  // "name:k=v,k2=v2" -> name and params.
  static std::pair<std::string, Params> parse_spec(const std::string& spec);
  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  bool has(const std::string& key) const { return values_.count(key) > 0; }

  int get_int(const std::string& key, int def, int lo, int hi);
  double get_double(const std::string& key, double def, double lo, double hi);
  std::string get_choice(const std::string& key, const std::string& def,
                         const std::set<std::string>& choices);
  bool get_bool(const std::string& key, bool def);
  // Throws InputError when a key was given but never read.
  void check_all_used() const;
  const std::map<std::string, std::string>& values() const { return values_; }
  nlohmann::json to_json() const;  // numbers as numbers where they parse
  void set_owner(std::string o) { owner_ = std::move(o); }
  // A dry run: a generator reads and checks its parameters, then returns an empty scene
  // without generating, so a whole suite is validated before any work starts.
  void set_dry_run(bool on) { dry_run_ = on; }
  bool dry_run() const { return dry_run_; }

 private:
  std::string owner_;
  std::map<std::string, std::string> values_;
  std::set<std::string> used_;
  bool dry_run_ = false;
};

}  // namespace vob
