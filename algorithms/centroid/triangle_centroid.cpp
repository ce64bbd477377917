#include "algorithms/centroid/triangle_centroid.h"

#include "algorithms/centroid/key_order.h"

namespace vob {
namespace {

class TriangleCentroid final : public Orderer {
 public:
  Claims claims() const override { return {}; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("centroids");
    const TriangleSoup& s = scene.soup();
    centroids_.resize(s.num_triangles());
    for (size_t t = 0; t < s.num_triangles(); ++t)
      centroids_[t] = (s.points[s.tris[t][0]] + s.points[s.tris[t][1]] + s.points[s.tris[t][2]]) / 3.0;
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    return order_by_descending_key(centroids_.size(), [&](size_t i) { return view.depth(centroids_[i]); },
                                   sort_, clock);
  }

  size_t bytes() const override {
    return centroids_.capacity() * sizeof(Vec3) + sort_.bytes();
  }

 private:
  std::vector<Vec3> centroids_;
  RadixArgsort sort_;
};

}  // namespace

OrdererInfo triangle_centroid_orderer_info() {
  return {"triangle-centroid", SceneKind::Triangles,
          "triangles sorted by centroid eye distance with the radix sort (heuristic)", {},
          [](const ResolvedParams&) -> std::unique_ptr<Orderer> { return std::make_unique<TriangleCentroid>(); }};
}

}  // namespace vob
