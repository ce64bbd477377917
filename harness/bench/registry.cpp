// The one file that includes plugin headers. Add a plugin: include its header, add a line.
#include "harness/bench/registry.h"

#include <algorithm>
#include <cctype>

#include "algorithms/centroid/centroid.h"
#include "algorithms/centroid/triangle_centroid.h"
#include "algorithms/centroid/vtk_centroid.h"
#include "algorithms/havs/gl/gl_race_probe.h"
#include "algorithms/havs/havs.h"
#include "algorithms/havs/havs_probes.h"
#include "algorithms/mpvo/mpvo.h"
#include "algorithms/stencil/stencil_layers.h"
#include "algorithms/stencil/stencil_probes.h"
#include "algorithms/stencil/stencil_xmpvo.h"
#include "algorithms/sxmpvo/sxmpvo.h"
#include "algorithms/sxmpvo/tiny_cells_probe.h"
#include "algorithms/voxel/distance_sort.h"
#include "algorithms/xmpvo/bsp_xmpvo.h"
#include "algorithms/xmpvo/stability_probe.h"
#include "algorithms/xmpvo/xmpvo.h"
#include "algorithms/voxel/grid_orderers.h"
#include "algorithms/voxel/voxel_probes.h"
#include "harness/bench/machine_limits.h"
#include "harness/bench/names.h"
#include "harness/bench/probe.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::deque<OrdererInfo>& mutable_registry() {
  static std::deque<OrdererInfo> registry = {
      centroid_orderer_info(),
      vtk_centroid_orderer_info(),
      mpvo_orderer_info(),
      mpvonc_orderer_info(),
      sxmpvo_orderer_info(),
      xmpvo_orderer_info(),
      bsp_xmpvo_orderer_info(),
      triangle_centroid_orderer_info(),
      stencil_layers_orderer_info(),
      stencil_xmpvo_orderer_info(),
      distance_sort_orderer_info(),
      btf_orderer_info(),
      wbtf_orderer_info(),
      pbtf_orderer_info(),
      ip_pbtf_orderer_info(),
      havs_orderer_info(),
  };
  return registry;
}
}  // namespace

const std::deque<OrdererInfo>& orderer_registry() { return mutable_registry(); }

void register_orderer(OrdererInfo info) {
  const bool plain = !info.name.empty() && std::all_of(info.name.begin(), info.name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (!plain) throw InputError("orderer", "'" + info.name + "'", "is not a plain name (letters, digits, '_', '-', '.')");
  for (const auto& known : orderer_registry())
    if (known.name == info.name) throw InputError("orderer", info.name, "is already registered");
  mutable_registry().push_back(std::move(info));
}

const OrdererInfo& find_orderer(const std::string& name) {
  for (const auto& info : orderer_registry())
    if (info.name == name) return info;
  std::vector<std::string> names;
  for (const auto& info : orderer_registry()) names.push_back(info.name);
  throw InputError("--algorithm", name, "unknown orderer (" + known_names_hint(name, names) + ")");
}

const OrdererInfo& spec_orderer(const std::string& spec) {
  return find_orderer(spec.substr(0, spec.find(':')));
}

ResolvedParams resolve_orderer_params(const std::string& spec) {
  auto [name, given] = Params::parse_spec(spec);
  return resolve_params(find_orderer(name).params, given);
}

// Probes: measurements that are not orderer x dataset x view (probe.h).
const std::vector<ProbeInfo>& probe_registry() {
  static const std::vector<ProbeInfo> registry = {
      xmpvo_stability_probe_info(),
      stencil_read_scan_probe_info(),
      stencil_layer_images_probe_info(),
      voxel_splat_frames_probe_info(),
      voxel_order_splits_probe_info(),
      sxmpvo_tiny_cells_probe_info(),
      machine_limits_probe_info(),
      havs_sorts_probe_info(),
      havs_analysis_probe_info(),
      havs_gl_probe_info(),
  };
  return registry;
}

const ProbeInfo& find_probe(const std::string& name) {
  for (const auto& info : probe_registry())
    if (info.name == name) return info;
  std::vector<std::string> names;
  for (const auto& info : probe_registry()) names.push_back(info.name);
  throw InputError("probe", name, "unknown probe (" + known_names_hint(name, names) + ")");
}

std::unique_ptr<Orderer> make_orderer(const std::string& spec) {
  const ResolvedParams params = resolve_orderer_params(spec);
  return spec_orderer(spec).make(params);
}

nlohmann::json resolved_parameters(const std::string& spec) {
  return resolve_orderer_params(spec).values();
}

}  // namespace vob
