#include "algorithms/voxel/voxel_probes.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/voxel/distance_sort.h"
#include "algorithms/voxel/grid_orderers.h"
#include "algorithms/voxel/grid_traversal.h"
#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

using json = nlohmann::json;

// The voxel plugins of this folder by spec ("ip-pbtf:interleave=explicit"), each prepared on
// its own fresh copy of the scene as the runner does.
struct Prepared {
  Scene scene;
  std::unique_ptr<Orderer> orderer;
};
std::unique_ptr<Prepared> prepare_voxel_orderer(const std::string& spec, const Scene& s) {
  auto [name, params] = Params::parse_spec(spec);
  const std::vector<OrdererInfo> infos = {btf_orderer_info(), wbtf_orderer_info(), pbtf_orderer_info(),
                                          ip_pbtf_orderer_info(), distance_sort_orderer_info()};
  auto it = std::find_if(infos.begin(), infos.end(), [&](const OrdererInfo& i) { return i.name == name; });
  if (it == infos.end())
    throw InputError("orderings", spec, "not a voxel orderer (btf, wbtf, pbtf, ip-pbtf, distance-sort)");
  auto p = std::make_unique<Prepared>();
  p->orderer = make_from_info(*it, params);
  params.check_all_used();
  p->scene = s.fresh();
  PhaseClock c;
  p->orderer->prepare(p->scene, c);
  return p;
}

// The order must be a permutation of the significant voxels (what the runner checks).
void check_complete(const Scene& s, std::vector<int32_t> order, const std::string& who) {
  std::sort(order.begin(), order.end());
  if (order != s.significant_voxels())
    throw std::logic_error(who + ": ordering is not a permutation of the significant voxels");
}

json splat_frames(Params& params, const ProbeContext& ctx) {
  const std::vector<std::string> specs = {"btf", "pbtf", "ip-pbtf"};  // the paper's Table 1 orderings
  const int frame_views = params.get_int("frame_views", 2, 1, 1000);
  if (params.dry_run()) return json::object();  // suite validation: parameters only
  const Scene& s = *ctx.scene;
  std::map<std::string, std::unique_ptr<Prepared>> prep;
  for (const auto& spec : specs) prep[spec] = prepare_voxel_orderer(spec, s);
  auto frame = [&](const std::string& spec, const Camera& cam) {
    const auto t0 = std::chrono::steady_clock::now();
    PhaseClock c;
    Ordering o = prep.at(spec)->orderer->order(cam, c);
    const Image img = render_in_order(s, cam, o.order);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    check_complete(s, std::move(o.order), spec);
    return t;
  };
  const size_t nv = std::min<size_t>(frame_views, ctx.views.size());
  if (nv == 0) throw InputError("frame_views", "", "the suite gives this probe no views");
  for (int w = 0; w < ctx.warmup; ++w)  // first-touch allocations
    for (const auto& spec : specs) frame(spec, ctx.views[0].second);
  json seconds = json::object(), views = json::array();
  for (const auto& spec : specs) seconds[spec] = json::array();
  for (size_t v = 0; v < nv; ++v) {
    const auto& [vi, cam] = ctx.views[v];
    std::map<std::string, std::vector<double>> t;
    for (int i = 0; i < ctx.repeats; ++i)
      for (const auto& spec : specs) t[spec].push_back(frame(spec, cam));
    for (const auto& spec : specs) seconds[spec].push_back(t[spec]);
    views.push_back(vi);
    if (ctx.progress) {
      std::string line = "  splat frames view " + std::to_string(vi) + ":";
      for (const auto& spec : specs)
        line += " " + spec + " " + std::to_string(1e3 * t[spec].front()).substr(0, 7) + " ms";
      ctx.progress(line);
    }
  }
  return {{"orderings", specs}, {"views", views}, {"seconds", seconds}};
}

int64_t positions_differing(const std::vector<int32_t>& a, const std::vector<int32_t>& b) {
  int64_t d = 0;
  for (size_t i = 0; i < a.size(); ++i) d += a[i] != b[i];
  return d;
}

json order_splits(Params& params, const ProbeContext& ctx) {
  if (params.dry_run()) return json::object();  // no parameters
  const Scene& s = *ctx.scene;
  const VoxelGrid& g = s.grid();
  const std::vector<std::string> specs = {"btf", "wbtf", "pbtf", "ip-pbtf"};
  std::map<std::string, std::unique_ptr<Prepared>> prep;
  for (const auto& spec : specs) prep[spec] = prepare_voxel_orderer(spec, s);
  // Significant voxels per slab of each axis: the material on each side of a plane.
  std::array<std::vector<int64_t>, 3> slab;
  for (int a = 0; a < 3; ++a) slab[a].assign(g.dims[a], 0);
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        if (g.significant(g.id(i, j, k))) ++slab[0][i], ++slab[1][j], ++slab[2][k];
  json out = json::array();
  for (const auto& [vi, cam] : ctx.views) {
    std::map<std::string, std::vector<int32_t>> orders;
    for (const auto& spec : specs) {
      PhaseClock c;
      orders[spec] = prep.at(spec)->orderer->order(cam, c).order;
    }
    const voxel::Splits sp = voxel::eye_splits(g, cam);
    json cuts = json::array();
    for (int a = 0; a < 3; ++a) {
      if (!sp[a].split()) continue;
      int below = 0, above = 0;
      for (int i = 0; i < g.dims[a]; ++i) (i < sp[a].kv ? below : above) += slab[a][i] > 0;
      cuts.push_back({{"axis", a}, {"kv", sp[a].kv}, {"e", sp[a].e}, {"slabs_below", below}, {"slabs_above", above}});
    }
    out.push_back({{"view", vi},
                   {"cuts", cuts},
                   {"pbtf_moved", positions_differing(orders["pbtf"], orders["btf"])},
                   {"ip_moved", positions_differing(orders["ip-pbtf"], orders["wbtf"])}});
  }
  return {{"views", out}};
}

}  // namespace

ProbeInfo voxel_splat_frames_probe_info() {
  return {"voxel-splat-frames",
          "whole software splatting frames (ordering + render_in_order) of voxel orderings, alternating",
          true, splat_frames};
}

ProbeInfo voxel_order_splits_probe_info() {
  return {"voxel-order-splits",
          "pbtf's dividing planes per view, occupied slabs on each side, where pbtf/ip-pbtf differ from btf/wbtf",
          true, order_splits};
}

}  // namespace vob
