#include "harness/cli/scene_args.h"

#include <sstream>

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
    throw InputError(what, s, "expected three finite numbers x,y,z");
  return v;
}
}  // namespace

void SceneArgs::add_to(CLI::App& cmd, bool validate_option) {
  cmd.add_option("--dataset,-d", dataset, "built-in dataset (see: vobench list)");
  cmd.add_option("--set", sets, "generator parameter k=v (repeatable)");
  cmd.add_option("--input,-i", input, "mesh or volume file (.vtu .vtk .vti .node .inr .off)");
  cmd.add_flag("--tetrahedralize", tetrahedralize, "mesh a closed .off surface with TetGen");
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
    if (!r.pairs.empty()) throw InputError(describe_overlap(source_name(spec), r));
  }
  return scene;
}

DatasetSpec SceneArgs::spec() const {
  if (dataset.empty() == input.empty())
    throw InputError("give exactly one of --dataset NAME or --input FILE");
  DatasetSpec s;
  s.name = dataset;
  s.input = input;
  s.tetrahedralize = tetrahedralize;
  if (!input.empty() && !sets.empty()) throw InputError("--set", sets[0], "applies to --dataset only");
  for (const auto& kv : sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", kv, "expected key=value");
    s.set[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return s;
}

void ViewArgs::add_to(CLI::App& cmd) {
  cmd.add_option("--views", views, "number of views on the Fibonacci sphere")->check(CLI::PositiveNumber);
  cmd.add_option("--view-index", view_index, "only this view of the set");
  cmd.add_option("--orbit", orbit, "use an orbit path of this many frames instead");
  cmd.add_option("--eye", eye, "explicit camera: eye x,y,z");
  cmd.add_option("--target", target, "explicit camera: target x,y,z");
  cmd.add_option("--up", up, "explicit camera: up x,y,z");
  cmd.add_option("--fov", fov, "vertical field of view in degrees (perspective)");
  cmd.add_option("--ortho", ortho, "orthographic view height (explicit camera)");
  cmd.add_flag("--ortho-views", ortho_views, "orthographic views for the view set");
  cmd.add_option("--zoom", zoom, "view set: move the eye closer by this factor");
  cmd.add_option("--size", size, "image size WxH");
}

std::vector<std::pair<int, Camera>> ViewArgs::cameras(const DatasetSpec& spec,
                                                      const Scene& scene) const {
  const auto [w, h] = parse_size(size);
  if (!eye.empty() || !target.empty()) {
    if (eye.empty() || target.empty()) throw InputError("--eye/--target", "camera", "give both");
    Camera c;
    c.eye = parse_vec(eye, "--eye");
    c.target = parse_vec(target, "--target");
    c.up = parse_vec(up, "--up");
    c.width = w;
    c.height = h;
    if (ortho > 0) {
      c.ortho = true;
      c.ortho_height = ortho;
    } else if (ortho < 0) {
      throw InputError("--ortho", std::to_string(ortho), "view height must be positive");
    } else {
      c.fov_deg = fov;
    }
    c.validate();
    return {{-1, c}};
  }
  if (!(zoom > 0)) throw InputError("--zoom", std::to_string(zoom), "must be positive");
  if (orbit > 0) {
    ViewOptions vo{w, h, ortho_views, zoom};
    std::vector<std::pair<int, Camera>> out;
    for (int f = 0; f < orbit; ++f)
      if (view_index < 0 || view_index == f) out.emplace_back(f, orbit_view(scene.bounds(), orbit, f, vo));
    if (out.empty()) throw InputError("--view-index", std::to_string(view_index), "is not a frame of the orbit");
    return out;
  }
  std::vector<int> idx;
  if (view_index >= 0) {
    if (view_index >= views)
      throw InputError("--view-index", std::to_string(view_index),
                       "is not in [0, " + std::to_string(views) + ")");
    idx.push_back(view_index);
  }
  auto out = dataset_views(spec, scene, views, idx, w, h, ortho_views, zoom);
  if (out.empty()) throw InputError("--view-index", std::to_string(view_index), "selects no view");
  for (auto& [i, c] : out) c.validate();
  return out;
}

nlohmann::json ViewArgs::describe() const {
  return {{"views", views}, {"view_index", view_index}, {"size", size}};
}

}  // namespace vob
