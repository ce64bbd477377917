#include "harness/bench/vtk_render_entry.h"

#include "harness/bench/registry.h"
#include "harness/bench/suite_reader.h"
#include "harness/scene/input_error.h"

namespace vob {

VtkRenderEntry read_vtk_render_entry(const SuiteReader& r, const nlohmann::json& e) {
  if (!e.is_object()) r.fail("vtk_render", "must be an object ({\"algorithms\": [...]})");
  r.only_keys(e, "vtk_render", {"algorithms", "repeats", "extinction", "comment"});
  VtkRenderEntry v;
  if (!e.contains("algorithms") || !e["algorithms"].is_array() || e["algorithms"].empty())
    r.fail("vtk_render.algorithms", "must be a non-empty list of orderer names");
  for (const auto& a : e["algorithms"]) {
    const std::string spec = r.string(a, "vtk_render.algorithms");
    const OrdererInfo* info = nullptr;
    try {
      info = &spec_orderer(spec);
    } catch (const InputError& err) {
      r.fail("vtk_render.algorithms", err.what());
    }
    if (info->kind != SceneKind::Cells) r.fail("vtk_render.algorithms: " + spec, "orders no cells");
    v.algorithms.push_back(spec);
  }
  if (e.contains("repeats")) v.repeats = r.integer(e["repeats"], "vtk_render.repeats", 1, 1000);
  if (e.contains("extinction")) v.extinction = r.number(e["extinction"], "vtk_render.extinction", 0, 1e6);
  return v;
}

}  // namespace vob
