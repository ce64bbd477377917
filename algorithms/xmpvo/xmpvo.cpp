#include "algorithms/xmpvo/xmpvo.h"

#include <cstdint>
#include <utility>
#include <vector>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/xmpvo/arrangement.h"
#include "algorithms/xmpvo/edge_contacts.h"
#include "algorithms/xmpvo/face_pairs.h"
#include "algorithms/xmpvo/projection.h"
#include "algorithms/xmpvo/ray_queries.h"
#include "algorithms/xmpvo/signs.h"
#include "algorithms/xmpvo/warped_quads.h"

namespace vob {
namespace {

using xmpvo::Mode;

// The phases, each in its own file: projection.h (facing, projected doubles, bucket
// grid), arrangement.h (vertices and edge crossings), ray_queries.h (relations).
class XmpvoOrderer final : public Orderer {
 public:
  explicit XmpvoOrderer(Mode mode) : mode_(mode) {}
  Claims claims() const override { return mpvo::core_claims(true, false); }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    core_.prepare(scene, clock);
    core_.set_plain_double_signs(mode_ == Mode::Double);
    { auto p = clock.phase("exterior faces"); ext_ = &scene.exterior_faces(); }
    {
      auto p = clock.phase("warped quads split");
      warped_quads_ = xmpvo::split_warped_quads(*ext_, split_);
      if (warped_quads_ > 0) ext_ = &split_;
    }
    {
      auto p = clock.phase("exterior face planes");
      plane_.resize(ext_->face.size());
      for (size_t i = 0; i < plane_.size(); ++i) plane_[i] = xmpvo::FacePlane::of(&ext_->corners[4 * i]);
    }
    { auto p = clock.phase("exterior edges"); arr_.set_faces(*ext_); }
    auto p = clock.phase("exterior edge contacts");
    contacts_ = xmpvo::find_edge_contacts(*ext_);
    const Aabb box = scene.mesh().bounds();
    centre_ = box.center();
    radius_ = box.radius();
  }

  Ordering order(const Camera& view, PhaseClock& clock) override;

  size_t bytes() const override {
    return core_.bytes() + exterior_bytes() + arrangement_bytes() + extra_.bytes() +
           pairs_.capacity() * 8;
  }

 private:
  size_t exterior_bytes() const {
    return plane_.capacity() * sizeof(xmpvo::FacePlane) + proj_.bytes() + split_.bytes();
  }
  size_t arrangement_bytes() const { return arr_.bytes() + queries_.bytes(); }
  void add_counters(Ordering& out, int64_t candidates) const;

  Mode mode_;
  mpvo::MpvoCore core_;
  const ExteriorFaces* ext_ = nullptr;  // the scene's, or split_
  ExteriorFaces split_;                 // the scene's with its warped quads split (warped_quads.h)
  size_t warped_quads_ = 0;
  std::vector<xmpvo::FacePlane> plane_;  // exact-filter planes of the exterior faces
  Vec3 centre_{};
  double radius_ = 0;
  // Per view.
  xmpvo::Signs signs_;
  xmpvo::Projection proj_;
  xmpvo::Arrangement arr_;
  xmpvo::QueryStats stats_;
  xmpvo::QueryScratch queries_;  // the ray queries' storage, kept from view to view
  xmpvo::EdgeContacts contacts_;  // view-independent, from prepare
  std::vector<std::pair<int32_t, int32_t>> pairs_;
  mpvo::ExtraRelations extra_;
};

Ordering XmpvoOrderer::order(const Camera& view, PhaseClock& clock) {
  Ordering out;
  signs_ = xmpvo::Signs{};
  signs_.mode = mode_;
  signs_.g = xmpvo::ViewGeometry::of(view);
  {
    auto p = clock.phase("I create partial order");
    core_.create_partial_order(view);
  }
  {
    auto p = clock.phase("project");
    proj_.run(*ext_, view, signs_, centre_, radius_);
  }
  int64_t candidates = 0;
  const bool conforming = contacts_.triangles_only && contacts_.touched_edges == 0;
  {
    auto p = clock.phase("arrangement vertices");
    // On a conforming surface the sweeps leave out the front sheet's inner edges, and the
    // arrangement their crossings with each other (edge_sweep.cpp).
    arr_.unswept_sheet = conforming && mode_ == xmpvo::Mode::Exact ? 1 : 0;
    candidates = arr_.build(*ext_, proj_, signs_);
  }
  {
    auto p = clock.phase("ray queries");
    xmpvo::QueryInput in{signs_, *ext_, plane_, proj_, arr_};
    in.conforming = conforming;
    xmpvo::view_relations(in, arr_, signs_, stats_, candidates, queries_, pairs_);
    signs_.side += stats_.side;
    signs_.dis_side += stats_.dis_side;
    extra_.build_from_pairs(core_.num_cells(), pairs_);
  }
  {
    auto p = clock.phase("DFS");
    core_.dfs_all(out, &extra_);
  }
  add_counters(out, candidates);
  return out;
}

void XmpvoOrderer::add_counters(Ordering& out, int64_t candidates) const {
  core_.add_counters(out);
  auto& k = out.counters;
  k["exterior_faces"] = static_cast<double>(ext_->face.size());
  k["warped_quads_split"] = static_cast<double>(warped_quads_);
  k["front_facing"] = static_cast<double>(proj_.front);
  k["back_facing"] = static_cast<double>(proj_.back);
  k["edge_on_faces"] = static_cast<double>(proj_.edge_on);
  k["faces_behind_eye"] = static_cast<double>(proj_.behind_eye);
  k["faces_crossing_eye_plane"] = static_cast<double>(proj_.crossing_eye);
  k["skipped_faces"] = static_cast<double>(proj_.crossing_eye);
  k["projected_vertices"] = static_cast<double>(arr_.projected_vertices);
  k["edge_crossings"] = static_cast<double>(arr_.vertices.size() - arr_.projected_vertices);
  k["candidate_edge_pairs"] = static_cast<double>(candidates);
  k["vertex_queries"] = static_cast<double>(stats_.vertex_queries);
  k["ray_queries"] = static_cast<double>(stats_.sectors);
  k["faces_per_query"] =
      stats_.sectors ? static_cast<double>(stats_.sector_faces) / stats_.sectors : 0.0;
  k["depth_order_calls"] = static_cast<double>(stats_.depth_calls);
  k["depth_order_full"] = static_cast<double>(stats_.depth_full);
  k["depth_undecided"] = static_cast<double>(stats_.depth_undecided);
  k["crossings_filtered"] = static_cast<double>(arr_.crossings_filtered);
  k["crossings_rechecked"] = static_cast<double>(arr_.crossings_rechecked);
  k["side_filtered"] = static_cast<double>(stats_.side_filtered);
  k["side_rechecked"] = static_cast<double>(stats_.side_rechecked);
  k["depth_rechecked"] = static_cast<double>(stats_.depth_rechecked);
  k["queries_rechecked"] = static_cast<double>(stats_.queries_rechecked);
  k["sweep_edges"] = static_cast<double>(stats_.sweep_edges);
  k["sweep_crossings"] = static_cast<double>(stats_.sweep_crossings);
  k["sweep_fallbacks"] = static_cast<double>(stats_.sweep_fallbacks);
  k["depth_plane_sides"] = static_cast<double>(stats_.depth_plane_sides);
  k["touched_exterior_edges"] = contacts_.triangles_only ? static_cast<double>(contacts_.touched_edges) : -1.0;
  k["sweep_swaps"] = static_cast<double>(stats_.sweep_swaps);
  k["depth_edge_orders"] = static_cast<double>(stats_.depth_edge_orders);
  k["sweep_end_queries"] = static_cast<double>(stats_.sweep_end_queries);
  k["sheet_edges_unswept"] = static_cast<double>(stats_.sheet_edges_unswept);
  k["arrangement_rebuilt"] = static_cast<double>(stats_.arrangement_rebuilt);
  k["degenerate_coverage"] = static_cast<double>(stats_.degenerate);
  k["relations"] = static_cast<double>(pairs_.size());
  k["grid_buckets"] = static_cast<double>(proj_.grid.buckets());
  if (mode_ == Mode::Compare) {
    k["facing_decisions"] = static_cast<double>(signs_.facing);
    k["side_decisions"] = static_cast<double>(signs_.side);
    k["crossing_decisions"] = static_cast<double>(signs_.crossing);
    k["disagree_facing"] = static_cast<double>(signs_.dis_facing);
    k["disagree_side"] = static_cast<double>(signs_.dis_side);
    k["disagree_crossing"] = static_cast<double>(signs_.dis_crossing);
    k["disagree_arrows"] = static_cast<double>(core_.double_sign_wrong());
  }
  k["bytes_mpvo"] = static_cast<double>(core_.bytes());
  k["bytes_faces"] =
      static_cast<double>(core_.faces().bytes() + core_.scene().face_planes().bytes());
  k["bytes_exterior"] = static_cast<double>(ext_->bytes() + exterior_bytes());
  k["bytes_arrangement"] = static_cast<double>(arrangement_bytes());
  k["bytes_relations"] = static_cast<double>(extra_.bytes() + pairs_.capacity() * 8);
}

}  // namespace

OrdererInfo xmpvo_orderer_info() {
  return {"xmpvo", SceneKind::Cells,
          "Silva et al.'s XMPVO: MPVO arrows plus exterior-cell relations from exact ray "
          "queries at the vertices of the projected exterior-edge arrangement (object exact)",
          {ParamSpec::choice("predicates", "exact", {"exact", "double", "compare"},
                             "sign arithmetic: exact predicates, plain doubles, or both compared "
                             "(double and compare are for the stability study)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            const std::string& m = p.get_choice("predicates");
            return std::make_unique<XmpvoOrderer>(m == "exact" ? Mode::Exact
                                                  : m == "double" ? Mode::Double : Mode::Compare);
          }};
}

}  // namespace vob
