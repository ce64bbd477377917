#include "algorithms/voxel/distance_sort.h"

#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

class DistanceSort final : public Orderer {
 public:
  Claims claims() const override {
    Claims c;
    c.object_exact = c.image_exact = true;  // in the splat oracle's sense: depth = eye distance
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("significant voxels");
    scene_ = scene;  // keeps the grid and the cached voxel list alive
    grid_ = &scene_.grid();
    ids_ = &scene_.significant_voxels();
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    const size_t n = ids_->size();
    {
      auto p = clock.phase("keys");
      keys_.resize(n);
      out_.resize(n);
      for (size_t i = 0; i < n; ++i) {
        keys_[i] = -view.depth(grid_->centre_of((*ids_)[i]));  // farthest first
        out_[i] = (*ids_)[i];
      }
    }
    {
      auto p = clock.phase("radix sort");
      radix_sort_by_key64(keys_, out_);
    }
    Ordering o;
    o.order = out_;
    return o;
  }

  size_t bytes() const override { return keys_.capacity() * 8 + out_.capacity() * 4; }

 private:
  Scene scene_;
  const VoxelGrid* grid_ = nullptr;
  const std::vector<int32_t>* ids_ = nullptr;
  std::vector<double> keys_;
  std::vector<int32_t> out_;
};

}  // namespace

OrdererInfo distance_sort_orderer_info() {
  return {"distance-sort", SceneKind::Voxels,
          "significant voxels sorted by eye distance (64-bit radix sort): the exact reference", {},
          [](const ResolvedParams&) -> std::unique_ptr<Orderer> { return std::make_unique<DistanceSort>(); }};
}

}  // namespace vob
