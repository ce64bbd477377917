// vobench check: run an orderer over views and judge every ordering with the oracle.
// The verdict is the one of the records (harness/bench/verdict.h): an orderer that
// composites itself (HAVS) is judged on what it composites ("judged": "composited"), the
// oracle's count on its derived cell order shown beside, labelled so.
// Exit 0: no violation in any view; 1: some violation; 2: bad usage or input, including
// cells the oracle sees overlapping (the input has no visibility order; no orderer is
// blamed) and --supersample > 1 for a compositing orderer.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "harness/bench/runner.h"
#include "harness/bench/verdict.h"
#include "harness/oracle/oracle.h"
#include "harness/cli/commands.h"
#include "harness/cli/paraview_files.h"
#include "harness/cli/scene_args.h"
#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::string overlap_fault_line(const std::string& source, const OracleResult& r, int view) {
  const nlohmann::json& e = r.overlap_examples.at(0);
  std::string line = source + ": cells " + std::to_string(e["cells"][0].get<int>()) + " and " +
                     std::to_string(e["cells"][1].get<int>()) + " overlap (sample at pixel " +
                     std::to_string(e["pixel"][0].get<int>()) + "," +
                     std::to_string(e["pixel"][1].get<int>());
  line += view >= 0 ? " of view " + std::to_string(view) : std::string(" of the camera");
  return line + ", " + std::to_string(r.overlapping_pairs) +
         " overlapping pairs): the input has no visibility order";
}
}  // namespace

Command add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "check an orderer with the oracle (exit 1 on a violation)");
  auto scene_args = std::make_shared<SceneArgs>();
  auto view_args = std::make_shared<ViewArgs>();
  auto algorithm = std::make_shared<std::string>();
  auto supersample = std::make_shared<int>(1);
  auto json = std::make_shared<bool>(false);
  auto images = std::make_shared<std::string>();
  cmd->add_option("--algorithm,-a", *algorithm, "orderer NAME[:k=v,...]")->required();
  scene_args->add_to(*cmd);
  view_args->add_to(*cmd);
  cmd->add_option("--supersample", *supersample, "S x S samples per pixel")->check(integer_in(1, 16));
  cmd->add_flag("--json", *json, "print the oracle's counts per view as JSON");
  cmd->add_option("--images", *images, "write order/exact/diff/violations PNGs of every view here, and for ParaView the violations as .vti and the camera as .pvcc");
  return [=]() {
    const DatasetSpec spec = scene_args->spec();
    view_args->validate(spec);
    check_algorithm(*algorithm, spec);
    std::error_code ec;
    if (!images->empty() && std::filesystem::exists(*images, ec) && !std::filesystem::is_directory(*images, ec))
      throw InputError("--images", "'" + *images + "'", "exists and is not a folder");
    const Scene scene = scene_args->load(spec);
    const auto cams = view_args->cameras(spec, scene);
    PreparedOrderer p = prepare_orderer(*algorithm, scene);
    OracleOptions oo;
    oo.supersample = *supersample;
    oo.violation_mask = !images->empty();
    nlohmann::json out{{"algorithm", *algorithm}, {"dataset", spec.to_json()},
                       {"judged", p.orderer->claims().composites ? "composited" : "order"},
                       {"primitives", scene.num_primitives()}, {"supersample", *supersample},
                       {"views", nlohmann::json::array()}};
    int failing = 0;
    int64_t cycles = 0;
    for (const auto& [vi, cam] : cams) {
      FrameMeasurement m = measure_frame(p, cam, 0, 1);
      check_complete(scene, m.ordering, *algorithm);
      const Verdict verdict = judge(*p.orderer, *algorithm, scene, cam, m.ordering, oo, "--supersample");
      const OracleResult& r = verdict.result;
      if (verdict.input_fault()) throw InputError(overlap_fault_line(source_name(spec), verdict.order_result(), vi));
      failing += r.ok() ? 0 : 1;
      cycles += m.ordering.cycles.cycles;
      nlohmann::json v = verdict.json();
      if (verdict.cell_order) v["oracle_cell_order"] = verdict.cell_order_json();
      v["view_index"] = vi;
      v["camera"] = cam.to_json();
      v["cycles"] = m.ordering.cycles.cycles;
      v["seconds"] = m.total_median();
      if (!images->empty()) {
        namespace fs = std::filesystem;
        const ShownImages shown = shown_images(*p.orderer, scene, cam, m.ordering);
        fs::create_directories(*images);
        const std::string stem = (fs::path(*images) / ("view" + std::to_string(vi))).string();
        write_png(shown.ordered, stem + "-order.png");
        write_png(shown.exact, stem + "-exact.png");
        write_png(difference_image(shown.ordered, shown.exact), stem + "-diff.png");
        write_png(violation_image(shown.exact, r.violation_mask), stem + "-violations.png");
        write_violation_vti(r, stem + "-violations.vti");  // ParaView: the mask and the camera
        write_camera_pvcc(cam, stem + ".pvcc");
        v["image_error"] = image_error(shown.ordered, shown.exact).to_json();
      }
      if (!*json) {
        const std::string pairs = r.pairs_counted ? "  pairs " + std::to_string(r.violating_pairs) : "";
        const std::string derived =
            verdict.cell_order ? "  (composited; derived cell order: violating pixels " +
                                     std::to_string(verdict.cell_order->violating_pixels) + ")"
                               : "";
        std::printf("view %3d: %s  covered %lld  violating pixels %lld  fragments %lld%s  max_k %d%s%s\n",
                    vi, r.ok() ? "ok  " : "FAIL", (long long)r.covered_pixels,
                    (long long)r.violating_pixels, (long long)r.violating_fragments, pairs.c_str(), r.max_k,
                    m.ordering.cycles.cycles ? ("  cycles " + std::to_string(m.ordering.cycles.cycles)).c_str() : "",
                    derived.c_str());
      }
      out["views"].push_back(v);
    }
    out["failing_views"] = failing;
    out["cycles"] = cycles;
    if (*json)
      std::cout << out.dump(2) << "\n";
    else
      std::printf("%s: %d of %zu views with violations (%s, %zu %s)\n", algorithm->c_str(), failing,
                  cams.size(), spec.label().c_str(), scene.num_primitives(),
                  scene_kind_name(scene.kind()));
    return failing ? 1 : 0;
  };
}

}  // namespace vob
