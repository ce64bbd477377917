#include "algorithms/centroid/centroid.h"

#include <algorithm>

#include "algorithms/centroid/key_order.h"

namespace vob {
namespace {

class CentroidOrderer final : public Orderer {
 public:
  explicit CentroidOrderer(bool view_key) : view_key_(view_key) {}
  Claims claims() const override { return {}; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("centroids");
    scene_ = scene;  // shares the data and cache: the centroids live as long as we do
    centroids_ = &scene_.cell_centroids().points;
    lo_ = {1e300, 1e300, 1e300}, hi_ = {-1e300, -1e300, -1e300};
    for (const Vec3& c : *centroids_)
      for (int a = 0; a < 3; ++a) lo_[a] = std::min(lo_[a], c[a]), hi_[a] = std::max(hi_[a], c[a]);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    const Vec3 f = view.forward();
    const bool by_view = view_key_ || view.ortho;  // orthographic: eye distance is view depth
    const Vec3* c = centroids_->data();
    const Vec3 eye = view.eye;
    const size_t n = centroids_->size();
    const KeyRange r = key_range_from_box(lo_, hi_, eye, f, by_view);
    const double kmin = r.lo, kmax = r.hi;
    // Two loops rather than a test per cell; the keys are the same doubles as before.
    if (by_view)
      return order_by_descending_key(n, [=](size_t i) { return dot(c[i] - eye, f); }, sort_, clock, kmin, kmax);
    return order_by_descending_key(n, [=](size_t i) { return length(c[i] - eye); }, sort_, clock, kmin, kmax);
  }

  size_t bytes() const override {
    return sort_.bytes();
  }

 private:
  bool view_key_;
  Scene scene_;
  const std::vector<Vec3>* centroids_ = nullptr;
  Vec3 lo_{1e300, 1e300, 1e300}, hi_{-1e300, -1e300, -1e300};  // the centroids' box
  RadixArgsort sort_;
};

}  // namespace

OrdererInfo centroid_orderer_info() {
  return {"centroid", SceneKind::Cells,
          "cell centroids sorted back to front with an LSD radix sort (heuristic)",
          {ParamSpec::choice("key", "eye", {"eye", "view"},
                             "sort key: distance from the eye to the centroid, or its depth along "
                             "the view direction (vtkCellCenterDepthSort's key)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<CentroidOrderer>(p.get_choice("key") == "view");
          }};
}

}  // namespace vob
