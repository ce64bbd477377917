#include "algorithms/mpvo/mpvo.h"

#include "algorithms/mpvo/mpvo_core.h"
#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

class MpvoOrderer final : public Orderer {
 public:
  explicit MpvoOrderer(mpvo::RenumberOption renumber) : renumber_(renumber) {}
  Claims claims() const override { return mpvo::core_claims(false, false); }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    core_.prepare(scene, clock, renumber_);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
    }
    {
      auto p = clock.phase("II DFS");
      core_.dfs_all(out);
    }
    core_.add_counters(out);
    return out;
  }

  size_t bytes() const override { return core_.bytes(); }

 private:
  mpvo::RenumberOption renumber_;
  mpvo::MpvoCore core_;
};

class MpvoncOrderer final : public Orderer {
 public:
  explicit MpvoncOrderer(mpvo::RenumberOption renumber) : renumber_(renumber) {}
  Claims claims() const override { return mpvo::core_claims(false, false); }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    core_.prepare(scene, clock, renumber_);
    const Scene& work = core_.scene();  // the input's, or its renumbered copy
    { auto p = clock.phase("cell centroids"); work.cell_centroids(); }
    centroids_ = &work.cell_centroids().points;
    marked_.assign(work.mesh().num_cells(), 0);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
    }
    {
      auto p = clock.phase("II sort exterior cells");
      sort_exterior_cells(view);
    }
    {
      auto p = clock.phase("III DFS");
      core_.begin_dfs(out);
      for (int32_t c : sort_.ids) core_.dfs_from(c, out);
      core_.dfs_sinks(out);
      core_.dfs_unvisited(out);
    }
    core_.add_counters(out);
    out.counters["exterior_cells"] = static_cast<double>(sort_.ids.size());
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + marked_.capacity() + sort_.bytes();
  }

 private:
  // Cells owning a front-facing boundary face, farthest centroid first.
  void sort_exterior_cells(const Camera& view) {
    const MeshFaces& faces = core_.faces();
    const Vec3 eye = view.eye, dir = view.forward();
    sort_.clear();
    for (int32_t f : faces.boundary) {
      if (!core_.front_facing_boundary(f)) continue;
      const int32_t c = faces.cell0[f];
      if (marked_[c]) continue;  // a cell may own several front-facing faces
      marked_[c] = 1;
      const Vec3 d = (*centroids_)[c] - eye;
      const double depth = view.ortho ? dot(d, dir) : length(d);
      sort_.push(static_cast<float>(-depth), c);  // ascending key = decreasing depth
    }
    for (int32_t c : sort_.ids) marked_[c] = 0;
    sort_.sort();
  }

  mpvo::RenumberOption renumber_;
  mpvo::MpvoCore core_;
  const std::vector<Vec3>* centroids_ = nullptr;
  std::vector<uint8_t> marked_;
  KeySort sort_;
};

}  // namespace

OrdererInfo mpvo_orderer_info() {
  return {"mpvo", SceneKind::Cells,
          "Williams' MPVO: face arrows and a DFS from the sink cells (exact on convex meshes)",
          mpvo::renumber_params(), [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<MpvoOrderer>(mpvo::renumber_option(p));
          }};
}

OrdererInfo mpvonc_orderer_info() {
  return {"mpvonc", SceneKind::Cells,
          "Williams' MPVONC: MPVO with a DFS first from exterior cells by decreasing centroid "
          "distance (heuristic)",
          mpvo::renumber_params(), [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<MpvoncOrderer>(mpvo::renumber_option(p));
          }};
}

}  // namespace vob
