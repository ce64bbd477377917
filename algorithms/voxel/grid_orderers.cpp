#include "algorithms/voxel/grid_orderers.h"

#include "algorithms/voxel/grid_traversal.h"

namespace vob {
namespace {

using namespace voxel;

enum class Mode { Btf, Wbtf, Pbtf, PbtfWbtf, IpImplicit, IpExplicit };

class GridOrderer final : public Orderer {
 public:
  explicit GridOrderer(Mode mode) : mode_(mode) {}

  Claims claims() const override { return {}; }  // heuristic: splats overlap across the grid order

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("runs per axis");
    scene_ = scene;  // keeps the grid alive
    grid_ = &scene_.grid();
    runs_ = build_run_index(*grid_);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Splits s;
    Permutation perm;
    Ordering o;
    {
      auto p = clock.phase("plan");
      const bool btf = mode_ == Mode::Btf || mode_ == Mode::Wbtf;
      s = btf ? view_direction_splits(*grid_, view) : eye_splits(*grid_, view);
      switch (mode_) {
        case Mode::Btf: case Mode::Pbtf: perm = fixed_permutation(); break;
        case Mode::Wbtf: case Mode::PbtfWbtf: perm = wbtf_permutation(view); break;
        default: perm = ip_permutation(view, s);
      }
      o.order.resize(runs_.significant);
    }
    TraversalStats st;
    {
      auto p = clock.phase("traverse");
      switch (mode_) {
        case Mode::IpImplicit: traverse_interleaved_implicit(runs_, s, perm, o.order.data(), st); break;
        case Mode::IpExplicit: traverse_interleaved_explicit(runs_, s, perm, o.order.data(), st); break;
        default: traverse_subvolumes(runs_, s, perm, o.order.data(), st);
      }
    }
    o.counters["visited"] = double(st.visited);
    o.counters["runs"] = double(st.runs);
    o.counters["subvolumes"] = double(st.subvolumes);
    o.counters["split_axes"] = split_axes(s);
    o.counters["occupied_split_axes"] = occupied_split_axes(s, runs_);
    o.counters["outer_axis"] = perm[0];
    return o;
  }

  size_t bytes() const override { return runs_.bytes(); }

 private:
  Mode mode_;
  Scene scene_;
  const VoxelGrid* grid_ = nullptr;
  RunIndex runs_;
};

}  // namespace

OrdererInfo btf_orderer_info() {
  return {"btf", SceneKind::Voxels,
          "Frieder et al. BTF: a traversal direction per axis from the view direction, fixed "
          "nesting z, y, x",
          {}, [](const ResolvedParams&) -> std::unique_ptr<Orderer> {
            return std::make_unique<GridOrderer>(Mode::Btf);
          }};
}

OrdererInfo wbtf_orderer_info() {
  return {"wbtf", SceneKind::Voxels,
          "Westover's BTF: axes nested by how perpendicular they are to the view plane", {},
          [](const ResolvedParams&) -> std::unique_ptr<Orderer> {
            return std::make_unique<GridOrderer>(Mode::Wbtf);
          }};
}

OrdererInfo pbtf_orderer_info() {
  return {"pbtf", SceneKind::Voxels,
          "Swan's PBTF: up to 8 subvolumes cut by the planes through the eye, one after the other",
          {ParamSpec::choice("permute", "fixed", {"fixed", "wbtf"},
                             "nesting inside each subvolume (fixed: z, y, x)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<GridOrderer>(p.get_choice("permute") == "wbtf" ? Mode::PbtfWbtf
                                                                                   : Mode::Pbtf);
          }};
}

OrdererInfo ip_pbtf_orderer_info() {
  return {"ip-pbtf", SceneKind::Voxels,
          "Botha and Post's IP-PBTF: PBTF subvolumes interleaved, outer axis not split",
          {ParamSpec::choice("interleave", "implicit", {"implicit", "explicit"},
                             "inner loop over runs (Algorithm 4) or counters over every grid "
                             "position (Algorithms 2, 3)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<GridOrderer>(p.get_choice("interleave") == "explicit"
                                                     ? Mode::IpExplicit
                                                     : Mode::IpImplicit);
          }};
}

}  // namespace vob
