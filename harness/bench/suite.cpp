#include "harness/bench/suite.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "datasets/datasets.h"
#include "harness/bench/json_input.h"
#include "harness/bench/registry.h"
#include "harness/scene/input_error.h"

namespace vob {

std::string DatasetSpec::label() const {
  if (!input.empty()) {
    const auto slash = input.find_last_of('/');
    return (slash == std::string::npos ? input : input.substr(slash + 1)) +
           (tetrahedralize ? "(tet)" : "");
  }
  std::string s = name;
  if (!set.empty()) {
    s += "(";
    bool first = true;
    for (const auto& [k, v] : set) {
      s += (first ? "" : ",") + k + "=" + v;
      first = false;
    }
    s += ")";
  }
  return s;
}

nlohmann::json DatasetSpec::to_json() const {
  nlohmann::json j;
  if (!input.empty()) {
    j["input"] = input;
    if (tetrahedralize) j["tetrahedralize"] = true;
  } else {
    j["name"] = name;
    Params p(name);
    for (const auto& [k, v] : set) p.set(k, v);
    j["set"] = p.to_json();
  }
  return j;
}

std::pair<int, int> parse_size(const std::string& s, const std::string& where) {
  // Strict: digits only on both sides of one 'x' (no sign, space or exponent).
  const auto number = [](std::string_view t, int& v) {
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return !t.empty() && ec == std::errc() && end == t.data() + t.size() &&
           std::isdigit(static_cast<unsigned char>(t.front()));
  };
  const auto x = s.find('x');
  int w = 0, h = 0;
  if (x != std::string::npos && number(std::string_view(s).substr(0, x), w) &&
      number(std::string_view(s).substr(x + 1), h) && w >= 1 && h >= 1 && w <= kMaxImageSide &&
      h <= kMaxImageSide)
    return {w, h};
  throw InputError(where, "'" + s + "'",
                   "expected WxH with 1 <= W, H <= " + std::to_string(kMaxImageSide));
}

Scene make_scene(const DatasetSpec& spec) {
  if (!spec.input.empty()) {
    InputOptions opt;
    opt.tetrahedralize = spec.tetrahedralize;
    return load_input(spec.input, opt);
  }
  Params p(spec.name);
  for (const auto& [k, v] : spec.set) p.set(k, v);
  return make_dataset(spec.name, p);
}

namespace {
// Reads the values of one suite file; every message names the file and the entry
// ("quick.json: datasets[1].set: ..."), and integers are range-checked as 64-bit values
// before they are narrowed.
class SuiteReader {
 public:
  explicit SuiteReader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    throw InputError(source_, where, why);
  }
  int integer(const nlohmann::json& v, const std::string& where, int64_t lo, int64_t hi) const {
    const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number_integer()) fail(where, v.dump().substr(0, 40) + " is not " + range);
    // nlohmann keeps non-negative integers unsigned: compare as unsigned first.
    if (v.is_number_unsigned() ? (v.get<uint64_t>() > static_cast<uint64_t>(hi) ||
                                  static_cast<int64_t>(v.get<uint64_t>()) < lo)
                               : (v.get<int64_t>() < lo || v.get<int64_t>() > hi))
      fail(where, v.dump() + " is not " + range);
    return static_cast<int>(v.get<int64_t>());
  }
  double number(const nlohmann::json& v, const std::string& where, double lo, double hi) const {
    const std::string range = "a number in (" + nlohmann::json(lo).dump() + ", " + nlohmann::json(hi).dump() + "]";
    if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > lo) ||
        !(v.get<double>() <= hi))
      fail(where, v.dump().substr(0, 40) + " is not " + range);
    return v.get<double>();
  }
  bool boolean(const nlohmann::json& v, const std::string& where) const {
    if (!v.is_boolean()) fail(where, "must be true or false");
    return v.get<bool>();
  }
  std::string string(const nlohmann::json& v, const std::string& where) const {
    if (!v.is_string() || v.get_ref<const std::string&>().empty()) fail(where, "must be a non-empty string");
    return v.get<std::string>();
  }
  const nlohmann::json& array(const nlohmann::json& v, const std::string& where) const {
    if (!v.is_array() || v.empty()) fail(where, "must be a non-empty array");
    return v;
  }
  void only_keys(const nlohmann::json& v, const std::string& where,
                 const std::set<std::string>& known) const {
    if (!v.is_object()) fail(where, "must be a JSON object");
    for (const auto& [k, _] : v.items())
      if (!known.count(k)) {
        std::string all;
        for (const auto& n : known) all += (all.empty() ? "" : ", ") + n;
        fail(where + (where.empty() ? "" : ".") + k, "is not a known key (known: " + all + ")");
      }
  }

 private:
  const std::string& source_;
};

// A generator parameter as Params reads it: integers exactly, other numbers as JSON writes
// them; arrays, objects and null are not parameters.
std::string parameter_text(const SuiteReader& r, const nlohmann::json& v, const std::string& where) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number() || v.is_boolean()) return v.dump();
  r.fail(where, "must be a number, a string or true/false");
}

DatasetSpec read_dataset(const SuiteReader& r, const nlohmann::json& d, const std::string& where) {
  r.only_keys(d, where, {"name", "set", "input", "tetrahedralize", "comment"});
  DatasetSpec ds;
  if (d.contains("name") == d.contains("input")) r.fail(where, "give exactly one of \"name\" or \"input\"");
  if (d.contains("input")) {
    ds.input = r.string(d["input"], where + ".input");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(ds.input, ec))
      r.fail(where + ".input", "'" + ds.input + "' is not a readable file");
    if (d.contains("tetrahedralize")) ds.tetrahedralize = r.boolean(d["tetrahedralize"], where + ".tetrahedralize");
    if (d.contains("set")) r.fail(where + ".set", "applies to generated datasets (\"name\") only");
    return ds;
  }
  ds.name = r.string(d["name"], where + ".name");
  if (d.contains("tetrahedralize")) r.fail(where + ".tetrahedralize", "applies to \"input\" files only");
  const auto& known = dataset_registry();
  if (std::none_of(known.begin(), known.end(), [&](const DatasetInfo& i) { return i.name == ds.name; }))
    r.fail(where + ".name", "'" + ds.name + "' is not a dataset (see: vobench list)");
  if (d.contains("set")) {
    if (!d["set"].is_object()) r.fail(where + ".set", "must be a JSON object of parameters");
    for (const auto& [k, v] : d["set"].items()) ds.set[k] = parameter_text(r, v, where + ".set." + k);
  }
  Params p(ds.name);
  for (const auto& [k, v] : ds.set) p.set(k, v);
  try {
    check_dataset_params(ds.name, p);
  } catch (const InputError& e) {
    r.fail(where + ".set", e.what());
  }
  return ds;
}

std::string read_algorithm(const SuiteReader& r, const nlohmann::json& a, const std::string& where) {
  const std::string spec = r.string(a, where);
  if (spec == "all") return spec;
  std::string name;
  try {
    name = Params::parse_spec(spec).first;
  } catch (const InputError& e) {
    r.fail(where, e.what());
  }
  const auto& known = orderer_registry();
  if (std::none_of(known.begin(), known.end(), [&](const OrdererInfo& i) { return i.name == name; }))
    r.fail(where, "'" + name + "' is not an orderer (see: vobench list)");
  try {
    make_orderer(spec);  // constructs only: parameters known and in range, nothing prepared
  } catch (const InputError& e) {
    r.fail(where, e.what());
  }
  return spec;
}

std::vector<int> read_view_list(const SuiteReader& r, const nlohmann::json& v, const std::string& where, int views) {
  std::vector<int> out;
  if (!v.is_array()) r.fail(where, "must be an array of view indices");
  for (size_t i = 0; i < v.size(); ++i)
    out.push_back(r.integer(v[i], where + "[" + std::to_string(i) + "]", 0, views - 1));
  return out;
}
}  // namespace

SuiteSpec SuiteSpec::from_json(const nlohmann::json& j, const std::string& source) {
  const SuiteReader r(source);
  if (!j.is_object()) r.fail("suite", "must be a JSON object");
  r.only_keys(j, "", {"name", "datasets", "algorithms", "views", "view_indices", "ortho", "zoom",
                      "sizes", "repeats", "warmup", "oracle", "supersample", "image_error",
                      "image_views", "images_of_violations", "comment"});
  SuiteSpec s;
  if (j.contains("name")) s.name = r.string(j["name"], "name");
  else s.name = "suite";
  if (!j.contains("datasets")) r.fail("datasets", "is missing");
  const auto& datasets = r.array(j["datasets"], "datasets");
  for (size_t i = 0; i < datasets.size(); ++i)
    s.datasets.push_back(read_dataset(r, datasets[i], "datasets[" + std::to_string(i) + "]"));
  if (!j.contains("algorithms")) r.fail("algorithms", "is missing");
  const auto& algorithms = r.array(j["algorithms"], "algorithms");
  for (size_t i = 0; i < algorithms.size(); ++i)
    s.algorithms.push_back(read_algorithm(r, algorithms[i], "algorithms[" + std::to_string(i) + "]"));
  if (j.contains("views")) s.views = r.integer(j["views"], "views", 1, kMaxViews);
  if (j.contains("view_indices")) s.view_indices = read_view_list(r, j["view_indices"], "view_indices", s.views);
  if (j.contains("ortho")) s.ortho = r.boolean(j["ortho"], "ortho");
  if (j.contains("zoom")) s.zoom = r.number(j["zoom"], "zoom", 0.0, kMaxZoom);
  if (j.contains("sizes")) {
    const auto& sizes = r.array(j["sizes"], "sizes");
    s.sizes.clear();
    for (size_t i = 0; i < sizes.size(); ++i) {
      const std::string where = "sizes[" + std::to_string(i) + "]";
      s.sizes.push_back(parse_size(r.string(sizes[i], where), source + ": " + where));
    }
  }
  if (j.contains("repeats")) s.repeats = r.integer(j["repeats"], "repeats", 1, kMaxRepeats);
  if (j.contains("warmup")) s.warmup = r.integer(j["warmup"], "warmup", 0, kMaxRepeats);
  if (j.contains("oracle")) s.oracle = r.boolean(j["oracle"], "oracle");
  if (j.contains("supersample")) s.supersample = r.integer(j["supersample"], "supersample", 1, 16);
  if (j.contains("image_error")) s.image_error = r.boolean(j["image_error"], "image_error");
  if (j.contains("image_views")) s.image_views = read_view_list(r, j["image_views"], "image_views", s.views);
  if (j.contains("images_of_violations"))
    s.images_of_violations = r.boolean(j["images_of_violations"], "images_of_violations");
  return s;
}

SuiteSpec SuiteSpec::load(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "suite", "is not a readable file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "suite", "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return from_json(parse_json_input(text.str(), path, "suite"), path);
}

}  // namespace vob
