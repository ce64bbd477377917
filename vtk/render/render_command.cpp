#include "vtk/render/render_command.h"

#include <filesystem>
#include <iostream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/external_orderer.h"
#include "harness/bench/jobs.h"
#include "harness/bench/registry.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"
#include "vtk/render/x_display.h"

namespace vob {

void RenderArgs::add_to(CLI::App& c) {
  cmd = &c;
  scene.add_to(c, false);
  view.add_to(c);
  c.add_option("--algorithm", settings.algorithms, "a vobench orderer drawn beside VTK's sort (repeatable)");
  c.add_option("--external", externals, "NAME=COMMAND: an external sorter (README), then --algorithm NAME");
  c.add_option("--timeout", timeout, "seconds per external sorter answer")->check(number_in(0, 1e6, true, false));
  c.add_option("--extinction", settings.extinction,
               "extinction as a multiple of vobench's compositor's (1: a typical ray through the bounding "
               "sphere has optical depth about 2)")
      ->check(number_in(0, 1e6, true, false));
  c.add_option("--repeats", settings.repeats, "timed frames per view and sorter")->check(integer_in(1, 1000));
  c.add_option("--suite", suite,
               "every cell dataset and size of a suite, with the orderers of its \"vtk_render\" entry "
               "({\"algorithms\": [...], \"repeats\": N, \"extinction\": F}), into OUT/vtk/LABEL-WxH");
  c.add_option("-o,--output", out, "output folder (render.json, render.html, PNGs)")->required();
}

namespace {
// VTK's X render window aborts the process without a display: say so first, as bad usage.
void require_x_display() {
  if (const std::string problem = x_display_problem(); !problem.empty())
    throw InputError("DISPLAY", problem, "no X server to open (VTK's OpenGL window needs one: run under xvfb-run -a)");
}

// The suite's "vtk_render" entry into `s`; InputError naming the suite and the key.
void read_vtk_entry(const std::string& path, RenderSettings& s) {
  const nlohmann::json j = read_json_file(path, "suite");
  if (!j.is_object() || !j.contains("vtk_render"))
    throw InputError(path, "vtk_render", "is missing (the orderers vobench-vtk draws: {\"algorithms\": [...]})");
  const nlohmann::json& e = j["vtk_render"];
  const auto bad = [&](const std::string& key, const std::string& why) {
    throw InputError(path, "vtk_render." + key, why);
  };
  if (!e.is_object()) bad("", "must be an object");
  for (const auto& [k, v] : e.items())
    if (k != "algorithms" && k != "repeats" && k != "extinction" && k != "comment")
      bad(k, "is not a known key (known: algorithms, repeats, extinction, comment)");
  if (!e.contains("algorithms") || !e["algorithms"].is_array() || e["algorithms"].empty())
    bad("algorithms", "must be a non-empty list of orderer names");
  for (const auto& a : e["algorithms"]) {
    if (!a.is_string()) bad("algorithms", "must hold strings");
    s.algorithms.push_back(a.get<std::string>());
  }
  if (e.contains("repeats")) {
    if (!e["repeats"].is_number_integer() || e["repeats"].get<int64_t>() < 1 || e["repeats"].get<int64_t>() > 1000)
      bad("repeats", "must be an integer in [1, 1000]");
    s.repeats = e["repeats"].get<int>();
  }
  if (e.contains("extinction")) {
    if (!e["extinction"].is_number() || !(e["extinction"].get<double>() > 0) || e["extinction"].get<double>() > 1e6)
      bad("extinction", "must be a number in (0, 1e6]");
    s.extinction = e["extinction"].get<double>();
  }
}

void print(const nlohmann::json& summary, const std::string& dir) {
  for (const auto& s : summary) std::cout << s.dump() << "\n";
  std::cout << "wrote " << dir << "/render.json and " << dir << "/render.html\n";
}

int run_suite(const RenderArgs& a, const std::string& command_line) {
  for (const char* opt : {"--dataset", "--input", "--set", "--algorithm", "--extinction", "--repeats", "--views",
                          "--view-index", "--orbit", "--eye", "--target", "--size", "--ortho-views", "--zoom"})
    if (a.cmd->count(opt)) throw InputError(opt, "with --suite", "the suite says it (its vtk_render entry, views, sizes)");
  const SuiteSpec suite = SuiteSpec::load(a.suite);
  RenderSettings s;
  read_vtk_entry(a.suite, s);
  for (const std::string& alg : s.algorithms)
    if (spec_orderer(alg).kind != SceneKind::Cells)
      throw InputError(a.suite, "vtk_render.algorithms: " + alg, "orders no cells");
  require_writable_folder(a.out);
  require_x_display();
  for (const DatasetSpec& ds : suite.datasets) {
    const Scene scene = make_scene(ds);
    if (scene.kind() != SceneKind::Cells) {
      std::cerr << "vobench-vtk: note: " << ds.row_label() << ": not cells, not drawn\n";
      continue;
    }
    for (const auto& [w, h] : suite.sizes) {
      const std::string dir = a.out + "/vtk/" + file_label(ds.row_label()) + "-" + std::to_string(w) + "x" +
                              std::to_string(h);
      std::filesystem::create_directories(dir);
      print(render_scene(scene, suite_views(suite, ds, scene, w, h), s, dir,
                         {{"tool", "vobench-vtk render"}, {"command", command_line}, {"suite", a.suite},
                          {"scene", ds.to_json()}}),
            dir);
    }
  }
  return 0;
}
}  // namespace

int run_render(const RenderArgs& a, const std::string& command_line) {
  for (const std::string& e : a.externals) {
    const auto eq = e.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--external", "'" + e + "'", "expected NAME=COMMAND");
    register_external_orderer(e.substr(0, eq), e.substr(eq + 1), SceneKind::Cells, a.timeout);
  }
  if (!a.suite.empty()) return run_suite(a, command_line);
  const DatasetSpec spec = a.scene.spec();
  a.view.validate(spec);
  for (const std::string& alg : a.settings.algorithms) check_algorithm(alg, spec);
  require_writable_folder(a.out);
  require_x_display();  // the options first: bad usage is named before a missing display
  const Scene scene = a.scene.load(spec);
  if (scene.kind() != SceneKind::Cells)
    throw InputError(source_name(spec), "scene", std::string("has ") + scene_kind_name(scene.kind()) +
                                                     "; the projected-tetrahedra mapper draws cells");
  std::filesystem::create_directories(a.out);
  print(render_scene(scene, a.view.cameras(spec, scene), a.settings, a.out,
                     {{"tool", "vobench-vtk render"}, {"command", command_line}, {"scene", spec.to_json()}}),
        a.out);
  return 0;
}

}  // namespace vob
