#include "harness/bench/suite.h"

#include <fstream>
#include <set>
#include <sstream>

#include "datasets/datasets.h"
#include "harness/bench/json_input.h"
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

std::pair<int, int> parse_size(const std::string& s) {
  const auto x = s.find('x');
  try {
    if (x != std::string::npos) {
      size_t a = 0, b = 0;
      const int w = std::stoi(s.substr(0, x), &a), h = std::stoi(s.substr(x + 1), &b);
      if (a == x && b == s.size() - x - 1 && w > 0 && h > 0 && w <= 16384 && h <= 16384)
        return {w, h};
    }
  } catch (const std::exception&) {
  }
  throw InputError("--size", s, "expected WxH with 1 <= W, H <= 16384");
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
std::string scalar_text(const nlohmann::json& v) {
  return v.is_string() ? v.get<std::string>() : v.dump();
}
}  // namespace

SuiteSpec SuiteSpec::from_json(const nlohmann::json& j, const std::string& source) {
  SuiteSpec s;
  try {
    static const std::set<std::string> known = {
        "name", "datasets", "algorithms", "views", "view_indices", "ortho", "zoom", "sizes",
        "repeats", "warmup", "oracle", "supersample", "image_error", "image_views",
        "images_of_violations", "comment"};
    for (const auto& [k, v] : j.items())
      if (!known.count(k)) throw InputError(source, "key '" + k + "'", "is not a suite key");
    s.name = j.value("name", std::string("suite"));
    for (const auto& d : j.at("datasets")) {
      DatasetSpec ds;
      if (d.contains("input")) {
        ds.input = d.at("input").get<std::string>();
        ds.tetrahedralize = d.value("tetrahedralize", false);
      } else {
        ds.name = d.at("name").get<std::string>();
        if (d.contains("set"))
          for (const auto& [k, v] : d.at("set").items()) ds.set[k] = scalar_text(v);
      }
      s.datasets.push_back(ds);
    }
    for (const auto& a : j.at("algorithms")) s.algorithms.push_back(a.get<std::string>());
    s.views = j.value("views", 14);
    if (j.contains("view_indices")) s.view_indices = j["view_indices"].get<std::vector<int>>();
    s.ortho = j.value("ortho", false);
    s.zoom = j.value("zoom", 1.0);
    if (j.contains("sizes")) {
      s.sizes.clear();
      for (const auto& z : j["sizes"]) s.sizes.push_back(parse_size(z.get<std::string>()));
    }
    s.repeats = j.value("repeats", 3);
    s.warmup = j.value("warmup", 1);
    s.oracle = j.value("oracle", true);
    s.supersample = j.value("supersample", 1);
    s.image_error = j.value("image_error", false);
    if (j.contains("image_views")) s.image_views = j["image_views"].get<std::vector<int>>();
    s.images_of_violations = j.value("images_of_violations", false);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, "suite", e.what());
  }
  if (s.datasets.empty()) throw InputError(source, "datasets", "is empty");
  if (s.algorithms.empty()) throw InputError(source, "algorithms", "is empty");
  if (s.views < 1) throw InputError(source, "views", "must be at least 1");
  if (s.repeats < 1 || s.warmup < 0) throw InputError(source, "repeats", "repeats >= 1, warmup >= 0");
  if (s.supersample < 1 || s.supersample > 16)
    throw InputError(source, "supersample", "must be in [1, 16]");
  if (!(s.zoom > 0)) throw InputError(source, "zoom", "must be positive");
  return s;
}

SuiteSpec SuiteSpec::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "suite", "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return from_json(parse_json_input(text.str(), path, "suite"), path);
}

}  // namespace vob
