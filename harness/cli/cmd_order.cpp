// vobench order: run one orderer for one view and write ORDER.json, enough for another
// program to verify the order independently.
#include <filesystem>
#include <iostream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/runner.h"
#include "harness/bench/verdict.h"
#include "harness/oracle/oracle.h"
#include "harness/cli/check_sources.h"
#include "harness/cli/commands.h"
#include "harness/cli/paraview_files.h"
#include "harness/cli/scene_args.h"
#include "harness/cli/thread_option.h"
#include "harness/cli/raster_option.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_order_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("order", "order one view and write ORDER.json");
  auto scene_args = std::make_shared<SceneArgs>();
  auto view_args = std::make_shared<ViewArgs>();
  auto algorithm = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto check = std::make_shared<bool>(false);
  auto vtu = std::make_shared<std::string>();
  cmd->add_option("--algorithm,-a", *algorithm, "orderer NAME[:k=v,...]")->required();
  scene_args->add_to(*cmd);
  view_args->add_to(*cmd);
  cmd->add_option("-o,--output", *out, "ORDER.json")->required();
  cmd->add_flag("--check", *check, "also store the verdict (the oracle's counts; HAVS: on what it composites)");
  cmd->add_option("--vtu", *vtu,
                  "also write the cell mesh as OUT.vtu for ParaView with cell arrays order_rank, "
                  "violating_fragments (the oracle on this order at this view) and in_cycle");
  auto threads = std::make_shared<ThreadOption>();
  threads->add_to(*cmd);
  auto raster = std::make_shared<RasterOption>();
  raster->add_to(*cmd);
  return [=]() {
    const auto limit = threads->limit();
    const DatasetSpec spec = scene_args->spec();
    view_args->validate(spec);
    if (!view_args->explicit_camera() && view_args->view_index < 0)
      throw InputError("--view-index", "view", "order writes one view: give --view-index I or an explicit camera (--eye/--target)");
    check_algorithm(*algorithm, spec);
    const Scene scene = scene_args->load(spec);
    const auto cams = view_args->cameras(spec, scene);
    const Camera& cam = cams[0].second;
    PreparedOrderer p = prepare_orderer(*algorithm, scene);
    FrameMeasurement m = measure_frame(p, cam, 0, 1);
    check_complete(scene, m.ordering, *algorithm);
    nlohmann::json j;
    j["algorithm"] = *algorithm;
    j["parameters"] = resolved_parameters(*algorithm);
    j["dataset"] = spec.to_json();
    if (j["dataset"].contains("input") && j["dataset"]["input"].is_string()) {  // found from any folder, and checked
      const std::string input = j["dataset"]["input"];
      j["dataset"]["input"] = std::filesystem::absolute(input).lexically_normal().string();
      j["dataset"]["input_fingerprint"] = input_fingerprint(input);
    }
    j["primitive_kind"] = scene_kind_name(scene.kind());
    j["primitives"] = scene.num_primitives();
    j["camera"] = cam.to_json();
    j["view_index"] = cams[0].first;
    j["threads"] = run_threads();
    j["order"] = m.ordering.order;
    j["cycles"] = {{"count", m.ordering.cycles.cycles}, {"primitives", m.ordering.cycles.primitives}};
    nlohmann::json prep = nlohmann::json::object(), phases = nlohmann::json::object();
    for (const auto& [n, s] : p.prepare_clock.phases()) prep[n] = s;
    for (const auto& [n, s] : m.repeats.back()) phases[n] = s;
    j["prepare_phases"] = prep;
    j["phases"] = phases;
    j["counters"] = m.ordering.counters;
    if (!m.ordering.layers.empty()) j["layers"] = m.ordering.layers;
    if (*check) {
      // The one verdict (verdict.h): a compositing orderer's is on what it composited.
      OracleOptions oo;
      oo.raster = raster->rule();
      const Verdict v = judge(*p.orderer, *algorithm, scene, cam, m.ordering, oo, "--supersample");
      j["raster"] = raster_rule_name(raster->rule());
      j["oracle"] = v.json();
      if (v.cell_order) j["oracle_cell_order"] = v.cell_order_json();
    }
    if (!vtu->empty()) {
      OracleOptions per_cell;
      per_cell.per_primitive = true;
      per_cell.raster = raster->rule();
      write_order_vtu(scene, m.ordering, check_ordering(scene, cam, m.ordering.order, per_cell), *vtu);
    }
    write_file_atomically(*out, j.dump() + "\n");
    std::cerr << "wrote " << *out << ": " << m.ordering.order.size() << " "
              << scene_kind_name(scene.kind()) << ", " << m.total_median() * 1e3 << " ms, " << run_threads()
              << " threads\n";
    return 0;
  };
}

}  // namespace vob
