#include "vtk/render/render_command.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/external_orderer.h"
#include "harness/bench/jobs.h"
#include "harness/bench/registry.h"
#include "harness/bench/suite.h"
#include "harness/cli/stop_signals.h"
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
  c.add_option("--xvfb", xvfb,
               "auto (default): when $DISPLAY opens no X server, start an Xvfb for this run and stop it at "
               "the end; never: exit 4 instead")
      ->check(CLI::IsMember({"auto", "never"}));
}

namespace {
// What names a scene's run: a finished one with the same key is not drawn again.
nlohmann::json run_key(const DatasetSpec& ds, const std::vector<std::pair<int, Camera>>& views,
                       const RenderSettings& s) {
  nlohmann::json v = nlohmann::json::array();
  for (const auto& [index, cam] : views) v.push_back({{"view_index", index}, {"camera", cam.to_json()}});
  return {{"scene", ds.to_json()}, {"algorithms", s.algorithms}, {"repeats", s.repeats},
          {"extinction", s.extinction}, {"views", v}};
}

bool same_run(const std::string& dir, const nlohmann::json& key) {
  std::ifstream in(dir + "/render.json");
  if (!in) return false;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() && j.value("run_key", nlohmann::json()) == key;
}

// `partial` becomes `dir`; an older `dir` goes only once the new one is complete.
void replace_folder(const std::string& partial, const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string old = dir + ".old";
  fs::remove_all(old);
  if (fs::exists(dir)) fs::rename(dir, old);
  fs::rename(partial, dir);
  fs::remove_all(old);
}

void print(const nlohmann::json& summary, const std::string& dir) {
  for (const auto& s : summary) std::cout << s.dump() << "\n";
  std::cout << "wrote " << dir << "/render.json and " << dir << "/render.html" << std::endl;  // now: a pipe buffers
}

int run_suite(const RenderArgs& a, const std::string& command_line) {
  for (const char* opt : {"--dataset", "--input", "--set", "--algorithm", "--extinction", "--repeats", "--views",
                          "--view-index", "--orbit", "--eye", "--target", "--size", "--ortho-views", "--zoom"})
    if (a.cmd->count(opt)) throw InputError(opt, "with --suite", "the suite says it (its vtk_render entry, views, sizes)");
  const SuiteSpec suite = SuiteSpec::load(a.suite);  // its vtk_render entry checked there
  if (!suite.vtk_render)
    throw InputError(a.suite, "vtk_render", "is missing (the orderers vobench-vtk draws: {\"algorithms\": [...]})");
  RenderSettings s;
  s.algorithms = suite.vtk_render->algorithms;
  s.repeats = suite.vtk_render->repeats;
  s.extinction = suite.vtk_render->extinction;
  require_writable_folder(a.out);
  const XServer x(a.xvfb == "auto");
  const StopSignals signals;
  s.stop = [] { return StopSignals::received(); };
  for (const DatasetSpec& ds : suite.datasets) {
    const Scene scene = make_scene(ds);
    if (scene.kind() != SceneKind::Cells) {
      std::cerr << "vobench-vtk: note: " << ds.row_label() << ": not cells, not drawn\n";
      continue;
    }
    for (const auto& [w, h] : suite.sizes) {
      const std::string dir = a.out + "/vtk/" + file_label(ds.row_label()) + "-" + std::to_string(w) + "x" +
                              std::to_string(h);
      const auto views = suite_views(suite, ds, scene, w, h);
      const nlohmann::json key = run_key(ds, views, s);
      if (same_run(dir, key)) {
        std::cout << "kept " << dir << " (render.json has this run_key)" << std::endl;
        continue;
      }
      const std::string partial = dir + ".partial";
      std::filesystem::remove_all(partial);
      std::filesystem::create_directories(partial);
      nlohmann::json summary;
      try {
        summary = render_scene(scene, views, s, partial,
                               {{"tool", "vobench-vtk render"}, {"command", command_line}, {"suite", a.suite},
                                {"scene", ds.to_json()}, {"run_key", key}, {"x_server", x.description()}});
      } catch (const RenderStopped&) {
        std::filesystem::remove_all(partial);  // no half scene; the finished ones stay
        throw;
      }
      replace_folder(partial, dir);
      print(summary, dir);
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
  const XServer x(a.xvfb == "auto");  // the options first: bad usage is named before a missing display
  const StopSignals signals;
  RenderSettings settings = a.settings;
  settings.stop = [] { return StopSignals::received(); };
  const Scene scene = a.scene.load(spec);
  if (scene.kind() != SceneKind::Cells)
    throw InputError(source_name(spec), "scene", std::string("has ") + scene_kind_name(scene.kind()) +
                                                     "; the projected-tetrahedra mapper draws cells");
  std::filesystem::create_directories(a.out);
  for (const char* stale : {"/render.json", "/render.html"})  // never beside images of another run
    std::filesystem::remove(a.out + stale);
  print(render_scene(scene, a.view.cameras(spec, scene), settings, a.out,
                     {{"tool", "vobench-vtk render"}, {"command", command_line}, {"scene", spec.to_json()},
                      {"x_server", x.description()}}),
        a.out);
  return 0;
}

}  // namespace vob
