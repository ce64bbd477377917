#include "harness/bench/suite.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "datasets/datasets.h"
#include "harness/bench/external_orderer.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/json_input.h"
#include "harness/bench/names.h"
#include "harness/bench/probe.h"
#include "harness/bench/registry.h"
#include "harness/bench/scale_overlay.h"
#include "harness/bench/suite_reader.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {
std::string params_text(const std::map<std::string, std::string>& set) {
  std::string s;
  for (const auto& [k, v] : set) s += (s.empty() ? "" : ",") + k + "=" + v;
  return s;
}
}  // namespace

std::string DatasetSpec::label() const {
  if (!input.empty()) {
    const auto slash = input.find_last_of('/');
    return (slash == std::string::npos ? input : input.substr(slash + 1)) +
           (tetrahedralize ? "(tet)" : "") + (variable.empty() ? "" : "[" + variable + "]");
  }
  return set.empty() ? name : name + "(" + params_text(set) + ")";
}

nlohmann::json DatasetSpec::to_json() const {
  nlohmann::json j;
  if (!input.empty()) {
    j["input"] = input;
    if (tetrahedralize) j["tetrahedralize"] = true;
    if (!variable.empty()) j["variable"] = variable;
  } else {
    j["name"] = name;
    Params p(name);
    for (const auto& [k, v] : set) p.set(k, v);
    j["set"] = p.to_json();
  }
  return j;
}

std::string ProbeSpec::label() const {
  return "probe:" + name + (set.empty() ? "" : "(" + params_text(set) + ")");
}

nlohmann::json ProbeSpec::parameters() const {
  Params p(name);
  for (const auto& [k, v] : set) p.set(k, v);
  return p.to_json();
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
    opt.variable = spec.variable;
    return load_input(spec.input, opt);
  }
  Params p(spec.name);
  for (const auto& [k, v] : spec.set) p.set(k, v);
  return make_dataset(spec.name, p);
}

namespace {

// "gap {gaps}" with gaps=5 -> "gap 5"; a {key} the point does not set is an error.
std::string fill_label(const SuiteReader& r, std::string label, const std::map<std::string, std::string>& set,
                       const std::string& where) {
  std::string out;
  for (size_t i = 0; i < label.size(); ++i) {
    const size_t close = label.find('}', i);
    if (label[i] != '{' || close == std::string::npos) {
      out += label[i];
      continue;
    }
    const std::string key = label.substr(i + 1, close - i - 1);
    if (!set.count(key)) r.fail(where, "{" + key + "} is not a parameter of this dataset");
    out += set.at(key);
    i = close;
  }
  return out;
}

// One dataset entry: one DatasetSpec per grid point.
std::vector<DatasetSpec> read_dataset(const SuiteReader& r, const nlohmann::json& d, const std::string& where) {
  r.only_keys(d, where, {"name", "set", "grid", "label", "input", "tetrahedralize", "variable", "comment"});
  DatasetSpec ds;
  if (d.contains("name") == d.contains("input")) r.fail(where, "give exactly one of \"name\" or \"input\"");
  const std::string label = d.contains("label") ? r.string(d["label"], where + ".label") : "";
  if (d.contains("input")) {
    ds.input = r.string(d["input"], where + ".input");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(ds.input, ec))
      r.fail(where + ".input", "'" + ds.input + "' is not a readable file");
    if (d.contains("tetrahedralize")) ds.tetrahedralize = r.boolean(d["tetrahedralize"], where + ".tetrahedralize");
    if (d.contains("variable")) ds.variable = r.string(d["variable"], where + ".variable");
    for (const char* k : {"set", "grid"})
      if (d.contains(k)) r.fail(where + "." + k, "applies to generated datasets (\"name\") only");
    ds.row = label;
    return {ds};
  }
  ds.name = r.string(d["name"], where + ".name");
  for (const char* k : {"tetrahedralize", "variable"})
    if (d.contains(k)) r.fail(where + "." + k, "applies to \"input\" files only");
  const auto& known = dataset_registry();
  if (std::none_of(known.begin(), known.end(), [&](const DatasetInfo& i) { return i.name == ds.name; })) {
    std::vector<std::string> names;
    for (const auto& i : known) names.push_back(i.name);
    r.fail(where + ".name", "'" + ds.name + "' is not a dataset (" + known_names_hint(ds.name, names) + ")");
  }
  const auto points = r.set_and_grid(d, where);
  if (points.size() > 1 && !label.empty() && label.find('{') == std::string::npos)
    r.fail(where + ".label", "must name the grid's keys as {key}, or every grid point gets the same row");
  std::vector<DatasetSpec> out;
  for (const auto& set : points) {
    ds.set = set;
    Params p(ds.name);
    for (const auto& [k, v] : ds.set) p.set(k, v);
    try {
      check_dataset_params(ds.name, p);
    } catch (const InputError& e) {
      r.fail(where + (d.contains("grid") ? ".grid" : ".set"), e.what());
    }
    ds.row = label.empty() ? "" : fill_label(r, label, set, where + ".label");
    out.push_back(ds);
  }
  return out;
}

std::vector<DatasetSpec> read_datasets(const SuiteReader& r, const nlohmann::json& list, const std::string& where) {
  std::vector<DatasetSpec> out;
  r.array(list, where);
  for (size_t i = 0; i < list.size(); ++i)
    for (auto& ds : read_dataset(r, list[i], where + "[" + std::to_string(i) + "]")) out.push_back(std::move(ds));
  return out;
}

void check_orderer(const SuiteReader& r, const std::string& spec, const std::string& where) {
  std::string name;
  try {
    name = Params::parse_spec(spec).first;
  } catch (const InputError& e) {
    r.fail(where, e.what());
  }
  const auto& known = orderer_registry();
  if (std::none_of(known.begin(), known.end(), [&](const OrdererInfo& i) { return i.name == name; })) {
    std::vector<std::string> names;
    for (const auto& i : known) names.push_back(i.name);
    r.fail(where, "'" + name + "' is not an orderer (" + known_names_hint(name, names) + ")");
  }
  try {
    make_orderer(spec);  // constructs only: parameters known and in range, nothing prepared
  } catch (const InputError& e) {
    r.fail(where, e.what());
  }
}

// An orderer that takes none of the suite's kinds of scene would silently run nothing.
void check_some_dataset_fits(const SuiteReader& r, const std::string& spec, const std::vector<DatasetSpec>& datasets,
                             const std::string& where) {
  if (spec == "all") return;
  const SceneKind kind = spec_orderer(spec).kind;
  std::string kinds;
  for (const auto& ds : datasets) {
    const SceneKind k = dataset_kind(ds);
    if (k == kind) return;
    if (kinds.find(scene_kind_name(k)) == std::string::npos) kinds += (kinds.empty() ? "" : ", ") + std::string(scene_kind_name(k));
  }
  r.fail(where, "'" + spec + "' orders " + scene_kind_name(kind) + "; no dataset of this suite is " +
                    scene_kind_name(kind) + " (they are " + kinds + "), so it would run nothing");
}

// {"name": "mine", "command": "CMD ARGS", "kind": "cells", "timeout": 60}: another program
// speaking the sorter protocol (external_orderer.h), registered under its name. "kind"
// defaults to the datasets' kind when they all have one.
std::string read_command_algorithm(const SuiteReader& r, const nlohmann::json& a, const std::string& where,
                                   const std::vector<DatasetSpec>& datasets) {
  r.only_keys(a, where, {"name", "command", "kind", "timeout", "comment"});
  if (!a.contains("name")) r.fail(where + ".name", "is missing");
  const std::string name = r.string(a["name"], where + ".name");
  const std::string command = r.string(a["command"], where + ".command");
  const double timeout =
      a.contains("timeout") ? r.number(a["timeout"], where + ".timeout", 0, 1e6) : kDefaultSorterTimeout;
  std::optional<SceneKind> kind;
  if (a.contains("kind")) {
    const std::string k = r.string(a["kind"], where + ".kind");
    for (SceneKind c : {SceneKind::Cells, SceneKind::Triangles, SceneKind::Voxels})
      if (k == scene_kind_name(c)) kind = c;
    if (!kind) r.fail(where + ".kind", "'" + k + "' is not cells, triangles or voxels");
  } else {
    for (const auto& ds : datasets) {
      const SceneKind k = dataset_kind(ds);
      if (kind && *kind != k) r.fail(where + ".kind", "is needed: the datasets are of several kinds");
      kind = k;
    }
  }
  try {
    register_external_orderer(name, command, *kind, timeout);
  } catch (const InputError& e) {
    r.fail(where + ".name", e.what());
  }
  return name;
}

// A string spec ("havs:k=6", "all") or {"name", "set", "grid"}: one spec per grid point.
std::vector<std::string> read_algorithm(const SuiteReader& r, const nlohmann::json& a, const std::string& where,
                                        const std::vector<DatasetSpec>& datasets) {
  if (a.is_string()) {
    const std::string spec = r.string(a, where);
    if (spec != "all") check_orderer(r, spec, where);
    return {spec};
  }
  if (a.is_object() && a.contains("command")) return {read_command_algorithm(r, a, where, datasets)};
  r.only_keys(a, where, {"name", "set", "grid", "comment"});
  if (!a.contains("name")) r.fail(where + ".name", "is missing");
  const std::string name = r.string(a["name"], where + ".name");
  std::vector<std::string> out;
  for (const auto& set : r.set_and_grid(a, where)) {
    const std::string spec = set.empty() ? name : name + ":" + params_text(set);
    check_orderer(r, spec, where);
    out.push_back(spec);
  }
  return out;
}

// A probe entry: one ProbeSpec per grid point, each checked by a dry run of the probe.
std::vector<ProbeSpec> read_probe(const SuiteReader& r, const nlohmann::json& e, const std::string& where,
                                  const SuiteSpec& suite) {
  r.only_keys(e, where, {"name", "set", "grid", "datasets", "repeats", "warmup", "comment"});
  if (!e.contains("name")) r.fail(where + ".name", "is missing");
  ProbeSpec p;
  p.name = r.string(e["name"], where + ".name");
  const auto& known = probe_registry();
  const auto info = std::find_if(known.begin(), known.end(), [&](const ProbeInfo& i) { return i.name == p.name; });
  if (info == known.end()) {
    std::vector<std::string> names;
    for (const auto& i : known) names.push_back(i.name);
    r.fail(where + ".name", "'" + p.name + "' is not a probe (" + known_names_hint(p.name, names) + ")");
  }
  p.repeats = e.contains("repeats") ? r.integer(e["repeats"], where + ".repeats", 1, kMaxRepeats) : suite.repeats;
  p.warmup = e.contains("warmup") ? r.integer(e["warmup"], where + ".warmup", 0, kMaxRepeats) : suite.warmup;
  if (e.contains("datasets")) p.datasets = read_datasets(r, e["datasets"], where + ".datasets");
  else if (info->needs_scene) p.datasets = suite.datasets;
  if (info->needs_scene && p.datasets.empty())
    r.fail(where, "probe '" + p.name + "' needs datasets: list them in the entry or the suite");
  std::vector<ProbeSpec> out;
  for (const auto& set : r.set_and_grid(e, where)) {
    p.set = set;
    Params params("probe " + p.name);
    for (const auto& [k, v] : set) params.set(k, v);
    params.set_dry_run(true);
    try {
      info->run(params, ProbeContext{});
      params.check_all_used();
    } catch (const InputError& err) {
      r.fail(where + (e.contains("grid") ? ".grid" : ".set"), err.what());
    }
    out.push_back(p);
  }
  return out;
}

std::vector<int> read_view_list(const SuiteReader& r, const nlohmann::json& v, const std::string& where, int views) {
  std::vector<int> out;
  if (!v.is_array()) r.fail(where, "must be an array of view indices");
  for (size_t i = 0; i < v.size(); ++i)
    out.push_back(r.integer(v[i], where + "[" + std::to_string(i) + "]", 0, views - 1));
  return out;
}

Vec3 read_vector(const SuiteReader& r, const nlohmann::json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 3 || !std::all_of(v.begin(), v.end(), [](const auto& x) { return x.is_number(); }))
    r.fail(where, "must be [x, y, z]");
  const Vec3 out{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  if (!(std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z)) || out.x * out.x + out.y * out.y + out.z * out.z == 0)
    r.fail(where, "must be a finite, non-zero vector");
  return out;
}

std::vector<ViewDirection> read_directions(const SuiteReader& r, const nlohmann::json& list) {
  std::vector<ViewDirection> out;
  r.array(list, "view_directions");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string where = "view_directions[" + std::to_string(i) + "]";
    r.only_keys(list[i], where, {"from", "up"});
    if (!list[i].contains("from")) r.fail(where + ".from", "is missing");
    ViewDirection d;
    d.from = read_vector(r, list[i]["from"], where + ".from");
    if (list[i].contains("up")) d.up = read_vector(r, list[i]["up"], where + ".up");
    const Vec3 c{d.from.y * d.up.z - d.from.z * d.up.y, d.from.z * d.up.x - d.from.x * d.up.z,
                 d.from.x * d.up.y - d.from.y * d.up.x};
    if (c.x * c.x + c.y * c.y + c.z * c.z == 0) r.fail(where + ".up", "is parallel to \"from\"");
    out.push_back(d);
  }
  return out;
}

void read_views(const SuiteReader& r, const nlohmann::json& j, SuiteSpec& s) {
  if (j.contains("views")) s.views = r.integer(j["views"], "views", 1, kMaxViews);
  const int ways = j.contains("view_indices") + j.contains("spread_views") + j.contains("view_directions");
  if (ways > 1) r.fail("view_indices", "give at most one of view_indices, spread_views, view_directions");
  if (j.contains("view_indices")) s.view_indices = read_view_list(r, j["view_indices"], "view_indices", s.views);
  if (j.contains("spread_views")) {
    const int m = r.integer(j["spread_views"], "spread_views", 1, s.views);
    for (int i = 0; i < m; ++i) s.view_indices.push_back(i * s.views / m);
  }
  if (j.contains("view_directions")) {
    s.view_directions = read_directions(r, j["view_directions"]);
    if (j.contains("views")) r.fail("views", "does not apply with view_directions (one view per direction)");
    s.views = static_cast<int>(s.view_directions.size());
  }
  if (j.contains("orbit")) s.orbit = r.boolean(j["orbit"], "orbit");
  if (s.orbit && !s.view_directions.empty()) r.fail("orbit", "does not apply with view_directions");
  if (j.contains("ortho")) s.ortho = r.boolean(j["ortho"], "ortho");
  if (j.contains("zoom")) s.zoom = r.number(j["zoom"], "zoom", 0.0, kMaxZoom);
  if (j.contains("fit")) s.fit = r.boolean(j["fit"], "fit");
  if (j.contains("sizes")) {
    const auto& sizes = r.array(j["sizes"], "sizes");
    s.sizes.clear();
    for (size_t i = 0; i < sizes.size(); ++i) {
      const std::string where = "sizes[" + std::to_string(i) + "]";
      s.sizes.push_back(parse_size(r.string(sizes[i], where), r.source() + ": " + where));
    }
  }
}
// "threads": N or [N, ...] (0: all cores), no count twice.
std::vector<int> read_threads(const SuiteReader& r, const nlohmann::json& t) {
  if (!t.is_array()) return {r.integer(t, "threads", 0, kMaxThreads)};
  if (t.empty()) r.fail("threads", "must list at least one thread count");
  std::vector<int> out;
  for (size_t i = 0; i < t.size(); ++i) {
    const int n = r.integer(t[i], "threads[" + std::to_string(i) + "]", 0, kMaxThreads);
    if (std::count(out.begin(), out.end(), n)) r.fail("threads[" + std::to_string(i) + "]", "repeats " + std::to_string(n));
    out.push_back(n);
  }
  return out;
}
}  // namespace

SuiteSpec SuiteSpec::from_json(const nlohmann::json& input, const std::string& source) {
  const SuiteReader r(source);
  if (!input.is_object()) r.fail("suite", "must be a JSON object");
  const nlohmann::json j = apply_scale(input, "default", source);
  r.only_keys(j, "", {"name", "datasets", "algorithms", "probes", "views", "view_indices", "spread_views",
                      "view_directions", "orbit", "ortho", "zoom", "fit", "sizes", "repeats", "warmup", "interleave", "threads", "oracle",
                      "supersample", "raster", "image_error", "image_views", "images_of_violations", "exterior_area",
                      "vtk_render", "comment"});
  SuiteSpec s;
  s.source = j;
  s.name = j.contains("name") ? r.string(j["name"], "name") : "suite";
  if (s.name.find_first_of("|/") != std::string::npos) r.fail("name", "must not contain '|' or '/'");
  if (j.contains("repeats")) s.repeats = r.integer(j["repeats"], "repeats", 1, kMaxRepeats);
  if (j.contains("warmup")) s.warmup = r.integer(j["warmup"], "warmup", 0, kMaxRepeats);
  if (j.contains("interleave")) s.interleave = r.boolean(j["interleave"], "interleave");
  if (j.contains("datasets")) s.datasets = read_datasets(r, j["datasets"], "datasets");
  if (!j.contains("probes")) {
    if (!j.contains("datasets")) r.fail("datasets", "is missing");
    if (!j.contains("algorithms")) r.fail("algorithms", "is missing");
  }
  if (j.contains("algorithms")) {
    const auto& algorithms = r.array(j["algorithms"], "algorithms");
    if (s.datasets.empty()) r.fail("algorithms", "need datasets");
    for (size_t i = 0; i < algorithms.size(); ++i)
      for (auto& spec : read_algorithm(r, algorithms[i], "algorithms[" + std::to_string(i) + "]", s.datasets)) {
        check_some_dataset_fits(r, spec, s.datasets, "algorithms[" + std::to_string(i) + "]");
        s.algorithms.push_back(std::move(spec));
      }
  }
  if (j.contains("probes")) {
    const auto& probes = r.array(j["probes"], "probes");
    for (size_t i = 0; i < probes.size(); ++i)
      for (auto& p : read_probe(r, probes[i], "probes[" + std::to_string(i) + "]", s)) s.probes.push_back(std::move(p));
  }
  read_views(r, j, s);
  if (j.contains("threads")) s.threads = read_threads(r, j["threads"]);
  if (j.contains("oracle")) s.oracle = r.boolean(j["oracle"], "oracle");
  if (j.contains("supersample")) s.supersample = r.integer(j["supersample"], "supersample", 1, 16);
  if (j.contains("raster")) {
    const std::string rule = r.string(j["raster"], "raster");
    if (rule != "exact" && rule != "gl") r.fail("raster", "'" + rule + "' is not a sampling rule (exact or gl)");
    s.raster = parse_raster_rule(rule, "raster");
    if (s.raster == RasterRule::gl && s.supersample != 1)
      r.fail("raster", "\"gl\" samples pixel centres only: supersample must be 1");
  }
  if (j.contains("image_error")) s.image_error = r.boolean(j["image_error"], "image_error");
  if (j.contains("image_views")) s.image_views = read_view_list(r, j["image_views"], "image_views", s.views);
  if (j.contains("images_of_violations"))
    s.images_of_violations = r.boolean(j["images_of_violations"], "images_of_violations");
  if (j.contains("exterior_area")) s.exterior_area = r.boolean(j["exterior_area"], "exterior_area");
  if (j.contains("vtk_render")) s.vtk_render = read_vtk_render_entry(r, j["vtk_render"]);
  return s;
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, what, "is not a readable file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, what, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_json_input(text.str(), path, what);
}

SuiteSpec SuiteSpec::load(const std::string& path) { return from_json(read_json_file(path, "suite"), path); }

}  // namespace vob
