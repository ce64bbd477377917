#include "harness/cli/scene_args.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"

namespace vob {

namespace {
Vec3 parse_vec(const std::string& s, const char* what) {
  Vec3 v;
  char c1 = 0, c2 = 0;
  std::istringstream in(s);
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !in.eof() ||
      !is_finite(v))
    throw InputError(what, "'" + s + "'", "expected three finite numbers x,y,z");
  return v;
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

CLI::Validator integer_in(int64_t lo, int64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        int64_t v = 0;
        const char* first = s.data();
        const char* last = s.data() + s.size();
        const bool digits = !s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) ||
                                           (s[0] == '-' && s.size() > 1));
        const auto [end, ec] = std::from_chars(first, last, v);
        if (!digits || ec != std::errc() || end != last || v < lo || v > hi)
          return "'" + s + "' is not an integer in " + range;
        return {};
      },
      "");  // the option's help text gives the range
}

CLI::Validator number_in(double lo, double hi, bool lo_open, bool hi_open) {
  const std::string range = std::string(lo_open ? "(" : "[") + number_text(lo) + ", " +
                            number_text(hi) + (hi_open ? ")" : "]");
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = s.empty() ? NAN : std::strtod(s.c_str(), &end);
        const bool ok = !s.empty() && *end == '\0' && std::isfinite(v) &&
                        (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
        if (!ok) return "'" + s + "' is not a number in " + range;
        return {};
      },
      "");
}

void check_algorithm(const std::string& algorithm, const DatasetSpec& spec) {
  make_orderer(algorithm);  // checks the name and parameters
  const OrdererInfo& info = spec_orderer(algorithm);
  if (spec.input.empty()) {
    const SceneKind kind = find_dataset(spec.name).kind;
    if (info.kind != kind)
      throw InputError("--algorithm", algorithm,
                       std::string("orders ") + scene_kind_name(info.kind) +
                           ", but dataset '" + spec.name + "' has " + scene_kind_name(kind));
  }
}

void SceneArgs::add_to(CLI::App& cmd, bool validate_option) {
  cmd.add_option("--dataset,-d", dataset, "built-in dataset (see: vobench list)");
  cmd.add_option("--set", sets, "generator parameter k=v (repeatable)");
  cmd.add_option("--input,-i", input,
                 "mesh, surface or volume file: cells .vtu .pvtu .vtk .node/.ele .msh (gmsh 2.2/4.1) "
                 ".exo/.e (Exodus II: all element blocks, time step 0, first nodal variable); "
                 "triangles .off .stl .ply .obj; voxels .vti .vtk .inr .inr.gz");
  cmd.add_flag("--tetrahedralize", tetrahedralize, "mesh a closed surface (.off .stl .ply .obj) with TetGen");
  cmd.add_option("--input-variable", variable, "Exodus II input: the nodal variable read as scalar (default: the first)");
  if (validate_option)
    cmd.add_option("--validate", validate,
                   "cells: per-cell checks (default); full: also find interpenetrating cells")
        ->check(CLI::IsMember({"cells", "full"}));
}

std::string source_name(const DatasetSpec& spec) {
  return spec.input.empty() ? spec.label() : spec.input;
}

Scene SceneArgs::load(const DatasetSpec& spec) const {
  Scene scene = make_scene(spec);
  if (validate == "full" && scene.kind() == SceneKind::Cells) {
    const CellOverlapReport r = check_overlapping_cells(scene.mesh(), scene.faces());
    if (!r.pairs.empty()) throw InputError(describe_overlap(source_name(spec), r, &scene.mesh()));
  }
  return scene;
}

DatasetSpec SceneArgs::spec() const {
  if (dataset.empty() == input.empty())
    throw InputError("--dataset/--input", "scene", "give exactly one of --dataset NAME or --input FILE");
  DatasetSpec s;
  s.name = dataset;
  s.input = input;
  s.tetrahedralize = tetrahedralize;
  s.variable = variable;
  if (!input.empty() && !sets.empty())
    throw InputError("--set", "'" + sets[0] + "'", "applies to --dataset only, not to --input");
  if (!dataset.empty() && !variable.empty())
    throw InputError("--input-variable", "'" + variable + "'", "applies to --input FILE.exo only, not to --dataset");
  if (!dataset.empty() && tetrahedralize)
    throw InputError("--tetrahedralize", "'" + dataset + "'", "applies to --input SURFACE (.off .stl .ply .obj) only, not to --dataset");
  for (const auto& kv : sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", "'" + kv + "'", "expected key=value");
    const std::string key = kv.substr(0, eq);
    if (s.set.count(key)) throw InputError("--set", key, "is given twice");
    s.set[key] = kv.substr(eq + 1);
  }
  if (!dataset.empty()) {
    Params p(dataset);
    for (const auto& [k, v] : s.set) p.set(k, v);
    check_dataset_params(dataset, p);
  }
  return s;
}

void ViewArgs::add_to(CLI::App& cmd) {
  cmd_ = &cmd;
  const std::string frames = std::to_string(kMaxViews);
  cmd.add_option("--views", views, "number of views on the Fibonacci sphere (1.." + frames + ")")
      ->check(integer_in(1, kMaxViews));
  cmd.add_option("--view-index", view_index, "only this view of the set (or frame of the orbit)")
      ->check(integer_in(0, kMaxViews - 1));
  cmd.add_option("--orbit", orbit, "use an orbit path of this many frames instead (1.." + frames + ")")
      ->check(integer_in(1, kMaxViews));
  cmd.add_option("--eye", eye, "explicit camera: eye x,y,z");
  cmd.add_option("--target", target, "explicit camera: target x,y,z");
  cmd.add_option("--up", up, "explicit camera: up x,y,z (default 0,0,1)");
  cmd.add_option("--fov", fov, "explicit camera: vertical field of view in degrees, in (0, 180)")
      ->check(number_in(0, 180, true, true));
  cmd.add_option("--ortho", ortho, "explicit camera: orthographic view height, positive")
      ->check(number_in(0, HUGE_VAL, true, true));
  cmd.add_flag("--ortho-views", ortho_views, "orthographic views for the view set or orbit");
  cmd.add_option("--zoom", zoom, "view set or orbit: move the eye closer by this factor, in (0, 100]")
      ->check(number_in(0, kMaxZoom, true, false));
  cmd.add_option("--size", size, "image size WxH, 1 <= W, H <= " + std::to_string(kMaxImageSide));
}

bool ViewArgs::given(const std::string& option) const {
  return cmd_ && cmd_->get_option(option)->count() > 0;
}

void ViewArgs::validate(const DatasetSpec& spec) const {
  parse_size(size);
  if (explicit_camera()) {
    if (eye.empty() || target.empty())
      throw InputError(eye.empty() ? "--eye" : "--target", "camera", "an explicit camera needs both --eye and --target");
    for (const char* o : {"--views", "--view-index", "--orbit", "--ortho-views", "--zoom"})
      if (given(o))
        throw InputError(o, "camera", "applies to view sets and orbits, not to an explicit camera (--eye/--target)");
    if (given("--fov") && given("--ortho"))
      throw InputError("--fov", "camera", "is a perspective angle, but --ortho asks for an orthographic camera");
    parse_vec(eye, "--eye");
    parse_vec(target, "--target");
    parse_vec(up, "--up");
    return;
  }
  for (const char* o : {"--fov", "--ortho", "--up"})
    if (given(o))
      throw InputError(o, "view set", "applies to an explicit camera (--eye/--target) only; view sets fit a 40 degree view to the scene");
  if (given("--orbit") && given("--views"))
    throw InputError("--views", "orbit", "an orbit has --orbit frames; give --views or --orbit, not both");
  const int frames = orbit > 0 ? orbit : views;
  if (view_index >= frames)
    throw InputError("--view-index", std::to_string(view_index),
                     "is not in [0, " + std::to_string(frames) + ")" + (orbit > 0 ? " (the orbit's frames)" : " (--views)"));
  if (orbit == 0 && spec.input.empty() && find_dataset(spec.name).views)
    for (const char* o : {"--views", "--ortho-views", "--zoom"})
      if (given(o))
        throw InputError(o, spec.name, "this dataset brings its own views; use --view-index, --orbit or an explicit camera");
}

std::vector<std::pair<int, Camera>> ViewArgs::cameras(const DatasetSpec& spec,
                                                      const Scene& scene) const {
  validate(spec);
  const auto [w, h] = parse_size(size);
  if (explicit_camera()) {
    Camera c;
    c.eye = parse_vec(eye, "--eye");
    c.target = parse_vec(target, "--target");
    c.up = parse_vec(up, "--up");
    c.width = w;
    c.height = h;
    if (given("--ortho")) {
      c.ortho = true;
      c.ortho_height = ortho;
    } else {
      c.fov_deg = fov;
    }
    c.validate();
    return {{-1, c}};
  }
  if (orbit > 0) {
    ViewOptions vo{w, h, ortho_views, zoom};
    std::vector<std::pair<int, Camera>> out;
    for (int f = 0; f < orbit; ++f)
      if (view_index < 0 || view_index == f) out.emplace_back(f, orbit_view(scene.bounds(), orbit, f, vo));
    return out;
  }
  std::vector<int> idx;
  if (view_index >= 0) idx.push_back(view_index);
  auto out = dataset_views(spec, scene, views, idx, w, h, ortho_views, zoom);
  if (out.empty())
    throw InputError("--view-index", std::to_string(view_index),
                     "selects no view of dataset " + spec.label() + " (it has its own views)");
  for (auto& [i, c] : out) c.validate();
  return out;
}

nlohmann::json ViewArgs::describe() const {
  return {{"views", views}, {"view_index", view_index}, {"size", size}};
}

}  // namespace vob
