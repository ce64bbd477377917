// vobench check: run an orderer over views and judge every ordering with the oracle.
// The verdict is the one of the records (harness/bench/verdict.h): an orderer that
// composites itself (HAVS) is judged on what it composites ("judged": "composited"), the
// oracle's count on its derived cell order shown beside, labelled so.
// The orderings come from a registered orderer (--algorithm), a file (--order ORDER.json,
// the format `vobench order` writes) or another program (--command, external_orderer.h).
// Exit 0: no violation in any view; 1: some violation; 2: bad usage or input, including
// cells the oracle sees overlapping (the input has no visibility order; no orderer is
// blamed; for cells with warped quads the line says that the oracle's planes are why),
// --supersample > 1 for a compositing orderer and a broken external sorter.
// With --max-violating-pixels / --max-rmse the exit is 1 only when a threshold is exceeded
// (a CI gate for heuristics); --junit writes one JUnit test case per view.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "harness/bench/external_orderer.h"
#include "harness/bench/junit.h"
#include "harness/bench/runner.h"
#include "harness/bench/verdict.h"
#include "harness/oracle/oracle.h"
#include "harness/cli/check_sources.h"
#include "harness/cli/commands.h"
#include "harness/cli/paraview_files.h"
#include "harness/cli/scene_args.h"
#include "harness/cli/thread_option.h"
#include "harness/cli/raster_option.h"
#include "harness/render/compositor.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::string overlap_fault_line(const std::string& source, const Scene& scene, const OracleResult& r, int view,
                               RasterRule rule) {
  const nlohmann::json& e = r.overlap_examples.at(0);
  const int a = e["cells"][0].get<int>(), b = e["cells"][1].get<int>();
  std::string line = source + ": cells " + std::to_string(a) + " and " + std::to_string(b) +
                     " overlap (sample at pixel " + std::to_string(e["pixel"][0].get<int>()) + "," +
                     std::to_string(e["pixel"][1].get<int>());
  line += view >= 0 ? " of view " + std::to_string(view) : std::string(" of the camera");
  line += ", " + std::to_string(r.overlapping_pairs) + " overlapping pairs): ";
  // Under the gl rule the cells are llvmpipe's snapped ones: snapping can invert a cell much
  // thinner than a pixel, and then the snapped mesh, not the file, has no visibility order.
  if (rule == RasterRule::gl) return line + "the cells as llvmpipe snaps them (--raster gl) have no visibility order";
  // Warped quads: the oracle takes each as a plane (cell_planes.h), and cells sharing only
  // an edge can overlap near it although their hulls do not (`vobench validate` says so).
  // Cells whose hulls interpenetrate overlap whatever the model: the plain line.
  const std::string cause = warped_quad_cause(scene.mesh(), a, b);
  if (!cause.empty() && !cells_interpenetrate(scene.mesh(), a, b))
    return line + cause + ", so as it models the cells the input has no visibility order " +
           "(`vobench validate` lists every such pair)";
  return line + "the input has no visibility order";
}

std::string percent_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g%%", v);
  return b;
}
}  // namespace

Command add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "check an orderer, an order file or a sorter program with the oracle (exit 1 on a "
                                          "violation, or with thresholds on one exceeded)");
  auto scene_args = std::make_shared<SceneArgs>();
  auto view_args = std::make_shared<ViewArgs>();
  auto algorithm = std::make_shared<std::string>();
  auto order_path = std::make_shared<std::string>();
  auto command = std::make_shared<std::string>();
  auto timeout = std::make_shared<double>(kDefaultSorterTimeout);
  auto supersample = std::make_shared<int>(1);
  auto json = std::make_shared<bool>(false);
  auto images = std::make_shared<std::string>();
  auto max_pixels = std::make_shared<double>(-1);
  auto max_rmse = std::make_shared<double>(-1);
  auto junit = std::make_shared<std::string>();
  cmd->add_option("--algorithm,-a", *algorithm, "orderer NAME[:k=v,...]");
  cmd->add_option("--order", *order_path,
                  "judge the permutation in this file (the format `vobench order` writes); its camera "
                  "and dataset unless view or scene options are given");
  cmd->add_option("--command", *command,
                  "judge another program speaking the sorter protocol (README \"Judging your own sorter\")");
  cmd->add_option("--timeout", *timeout, "--command: seconds to wait for each answer (default 60)")
      ->check(number_in(0, 1e6, true, false));
  scene_args->add_to(*cmd);
  view_args->add_to(*cmd);
  cmd->add_option("--supersample", *supersample, "S x S samples per pixel")->check(integer_in(1, 16));
  cmd->add_flag("--json", *json, "print the oracle's counts per view as JSON");
  cmd->add_option("--images", *images, "write order/exact/diff/violations PNGs of every view here, and for ParaView the violations as .vti and the camera as .pvcc");
  cmd->add_option("--max-violating-pixels", *max_pixels,
                  "pass (exit 0) when violating pixels are at most PCT percent of the covered pixels of all views")
      ->check(number_in(0, 100, false, false));
  cmd->add_option("--max-rmse", *max_rmse,
                  "pass (exit 0) when every view's image RMSE against the exact composite is at most X")
      ->check(number_in(0, 1e9, false, false));
  cmd->add_option("--junit", *junit, "write JUnit XML here: one test case per view, the counts in its message");
  auto threads = std::make_shared<ThreadOption>();
  threads->add_to(*cmd);
  auto raster = std::make_shared<RasterOption>();
  raster->add_to(*cmd);
  return [=]() {
    const auto limit = threads->limit();
    const int sources = !algorithm->empty() + !order_path->empty() + !command->empty();
    if (sources != 1)
      throw InputError("--algorithm/--order/--command", "orderings", "give exactly one of --algorithm NAME, --order FILE or --command \"CMD ARGS\"");
    if (cmd->get_option("--timeout")->count() && command->empty())
      throw InputError("--timeout", "orderings", "applies to --command only");
    std::optional<OrderFile> file;
    if (!order_path->empty()) {
      file = read_order_file(*order_path);
      scene_from_order_file(*file, *scene_args);
    }
    const DatasetSpec spec = scene_args->spec();
    view_args->validate(spec);
    if (!algorithm->empty()) check_algorithm(*algorithm, spec);
    std::error_code ec;
    if (!images->empty() && std::filesystem::exists(*images, ec) && !std::filesystem::is_directory(*images, ec))
      throw InputError("--images", "'" + *images + "'", "exists and is not a folder");
    if (!junit->empty() && std::filesystem::is_directory(*junit, ec))
      throw InputError("--junit", "'" + *junit + "'", "is a folder, not a file");
    // The file's camera unless the command line chooses views.
    bool view_options = false;
    for (const char* o : {"--views", "--view-index", "--orbit", "--eye", "--target", "--up", "--fov", "--ortho",
                          "--ortho-views", "--zoom", "--size"})
      view_options = view_options || cmd->get_option(o)->count() > 0;
    if (file && !view_options && !file->camera)
      throw InputError(file->path, "camera", "is not in the file: give view options (--views, --eye/--target, ...)");
    if (file && view_options && file->camera)  // an order is of one view: judging it at others says nothing
      throw InputError(file->path, "camera", "is in the file (the view its order is of): drop the view options "
                                             "(--views, --size, --eye, ...) or order again at those views");
    const Scene scene = scene_args->load(spec);
    const auto cams = file && !view_options ? std::vector<std::pair<int, Camera>>{{file->view_index, *file->camera}}
                                            : view_args->cameras(spec, scene);
    PreparedOrderer p = file               ? prepare_fixed_order(*file, scene)
                        : !command->empty() ? prepare_command(*command, *timeout, scene)
                                            : prepare_orderer(*algorithm, scene);
    const std::string label = file ? file->label : !command->empty() ? *command : *algorithm;
    const bool gated = *max_pixels >= 0 || *max_rmse >= 0;
    const bool want_error = !images->empty() || *max_rmse >= 0;
    OracleOptions oo;
    oo.supersample = *supersample;
    oo.raster = raster->rule();
    oo.violation_mask = !images->empty();
    nlohmann::json out{{"algorithm", label}, {"dataset", spec.to_json()},
                       {"judged", p.orderer->claims().composites ? "composited" : "order"},
                       {"primitives", scene.num_primitives()}, {"supersample", *supersample},
                       {"raster", raster_rule_name(raster->rule())},
                       {"threads", run_threads()},
                       {"views", nlohmann::json::array()}};
    if (file) out["order_file"] = file->path;
    if (!command->empty()) out["command"] = *command;
    int failing = 0;
    int64_t cycles = 0, covered = 0, violating = 0, rule_cycle_pixels = 0;
    int rule_cycle_views = 0;  // ok views whose violations all lie on the gl rule's cycles
    double worst_rmse = 0;
    std::vector<JunitCase> cases;
    for (const auto& [vi, cam] : cams) {
      set_external_view_index(*p.orderer, vi);
      FrameMeasurement m = measure_frame(p, cam, 0, 1);
      check_complete(scene, m.ordering, label);
      const Verdict verdict = judge(*p.orderer, label, scene, cam, m.ordering, oo, "--supersample");
      const OracleResult& r = verdict.result;
      if (verdict.input_fault()) throw InputError(overlap_fault_line(source_name(spec), scene, verdict.order_result(), vi, raster->rule()));
      failing += r.ok() ? 0 : 1;
      if (r.ok() && r.violating_fragments > 0) ++rule_cycle_views, rule_cycle_pixels += r.violating_pixels;
      cycles += m.ordering.cycles.cycles;
      covered += r.covered_pixels;
      violating += r.violating_pixels;
      nlohmann::json v = verdict.json();
      if (verdict.cell_order) v["oracle_cell_order"] = verdict.cell_order_json();
      v["view_index"] = vi;
      v["camera"] = cam.to_json();
      v["cycles"] = m.ordering.cycles.cycles;
      v["seconds"] = m.total_median();
      nlohmann::json phases = nlohmann::json::object();
      for (const auto& [n, s] : m.repeats.back()) phases[n] = s;
      v["phases"] = phases;
      std::optional<ImageError> err;
      if (want_error) {
        const ShownImages shown = shown_images(*p.orderer, scene, cam, m.ordering);
        err = image_error(shown.ordered, shown.exact);
        v["image_error"] = err->to_json();
        worst_rmse = std::max(worst_rmse, err->rmse);
        if (!images->empty()) {
          namespace fs = std::filesystem;
          fs::create_directories(*images);
          const std::string stem = (fs::path(*images) / ("view" + std::to_string(vi))).string();
          write_png(shown.ordered, stem + "-order.png");
          write_png(shown.exact, stem + "-exact.png");
          write_png(difference_image(shown.ordered, shown.exact), stem + "-diff.png");
          write_png(violation_image(shown.exact, r.violation_mask), stem + "-violations.png");
          write_violation_vti(r, stem + "-violations.vti");  // ParaView: the mask and the camera
          write_camera_pvcc(cam, stem + ".pvcc");
        }
      }
      const double pct = r.covered_pixels ? 100.0 * r.violating_pixels / r.covered_pixels : 0.0;
      std::string counts = "violating pixels " + std::to_string(r.violating_pixels) + " of " +
                           std::to_string(r.covered_pixels) + " covered (" + percent_text(pct) + "), fragments " +
                           std::to_string(r.violating_fragments) +
                           (r.pairs_counted ? ", pairs " + std::to_string(r.violating_pairs) : "") + ", max_k " +
                           std::to_string(r.max_k);
      if (err) counts += ", rmse " + short_number(err->rmse);
      // A view's case fails as the exit code does: on a violation, or with thresholds on its
      // own RMSE over --max-rmse (a per-view limit); --max-violating-pixels is a limit over all
      // views together, its own case below (a view over it alone once failed the JUnit file
      // of a check that passed).
      const bool view_failed = gated ? (err && *max_rmse >= 0 && err->rmse > *max_rmse) : !r.ok();
      cases.push_back({vi >= 0 ? "view " + std::to_string(vi) : "camera", "vobench.check." + label,
                       m.total_median(), view_failed, counts});
      if (!*json) {
        const std::string pairs = r.pairs_counted ? "  pairs " + std::to_string(r.violating_pairs) : "";
        const std::string derived =
            verdict.cell_order ? "  (composited; derived cell order: violating pixels " +
                                     std::to_string(verdict.cell_order->violating_pixels) + ")"
                               : "";
        const std::string rmse = err ? "  rmse " + short_number(err->rmse) : "";
        std::string on_cycles;
        if (r.rule_cycles) {  // rule_cycles.h
          const RuleCycles& c = *r.rule_cycles;
          on_cycles = "  [gl rule cycles: " + std::to_string(c.components) + " (largest " +
                      std::to_string(c.largest) + " primitives); pixels on them " + std::to_string(c.cycle_pixels) +
                      ", avoidable " + std::to_string(c.avoidable_pixels) + "; pairs forced " +
                      std::to_string(c.forced_pairs) + ", excess " + std::to_string(c.excess) +
                      (c.unbounded ? ", components without a minimum " + std::to_string(c.unbounded) : "") + "]";
        }
        const std::string name = vi >= 0 ? "view " + std::string(vi < 10 ? "  " : vi < 100 ? " " : "") + std::to_string(vi)
                                         : "camera  ";
        std::printf("%s: %s  covered %lld  violating pixels %lld  fragments %lld%s  max_k %d%s%s%s%s\n",
                    name.c_str(), r.ok() ? "ok  " : "FAIL", (long long)r.covered_pixels,
                    (long long)r.violating_pixels, (long long)r.violating_fragments, pairs.c_str(), r.max_k,
                    m.ordering.cycles.cycles ? ("  cycles " + std::to_string(m.ordering.cycles.cycles)).c_str() : "",
                    rmse.c_str(), derived.c_str(), on_cycles.c_str());
      }
      out["views"].push_back(v);
    }
    finish_external_orderer(*p.orderer);  // a sorter failing at its exit fails the check (exit 2)
    const double pct = covered ? 100.0 * violating / covered : 0.0;
    bool passed = failing == 0;
    std::string gate_line;
    if (gated) {
      passed = true;
      if (*max_pixels >= 0) {
        const bool ok = pct <= *max_pixels;
        passed = passed && ok;
        gate_line += "violating pixels " + percent_text(pct) + " of covered (limit " + percent_text(*max_pixels) +
                     "): " + (ok ? "pass" : "FAIL");
      }
      if (*max_rmse >= 0) {
        const bool ok = worst_rmse <= *max_rmse;
        passed = passed && ok;
        gate_line += std::string(gate_line.empty() ? "" : "; ") + "worst rmse " + short_number(worst_rmse) +
                     " (limit " + short_number(*max_rmse) + "): " + (ok ? "pass" : "FAIL");
      }
      if (*max_pixels >= 0)
        cases.push_back({"violating pixels over all views", "vobench.check." + label, 0.0, pct > *max_pixels,
                         "violating pixels " + percent_text(pct) + " of covered (limit " + percent_text(*max_pixels) +
                             ")"});
      out["thresholds"] = {{"max_violating_pixels", *max_pixels >= 0 ? nlohmann::json(*max_pixels) : nlohmann::json()},
                           {"max_rmse", *max_rmse >= 0 ? nlohmann::json(*max_rmse) : nlohmann::json()}};
      if (*max_rmse >= 0) out["worst_rmse"] = worst_rmse;
    }
    out["failing_views"] = failing;
    out["rule_cycle_views"] = rule_cycle_views;
    out["rule_cycle_pixels"] = rule_cycle_pixels;
    out["cycles"] = cycles;
    out["covered_pixels"] = covered;
    out["violating_pixels"] = violating;
    out["violating_pixel_percent"] = pct;
    out["passed"] = passed;
    if (!junit->empty()) write_junit(*junit, "vobench check " + label + " on " + spec.label(), cases);
    if (*json)
      std::cout << out.dump(2) << "\n";
    else {
      std::printf("%s: %d of %zu views with violations%s (%s, %zu %s, %d threads)\n", label.c_str(), failing,
                  cams.size(), rule_cycle_views ? " beyond the gl rule's cycles" : "", spec.label().c_str(), scene.num_primitives(),
                  scene_kind_name(scene.kind()), run_threads());
      if (rule_cycle_views)
        std::printf("%d views pass with %lld violating pixels that lie on cycles of the gl rule's precedence "
                    "graph, as few as any order has there (rule_cycles.h)\n",
                    rule_cycle_views, (long long)rule_cycle_pixels);
      if (gated) std::printf("%s\n", gate_line.c_str());
    }
    return passed ? 0 : 1;
  };
}

}  // namespace vob
