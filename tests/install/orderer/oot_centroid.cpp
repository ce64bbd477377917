// oot-centroid: cells back to front by the eye distance of their centroids (std::sort, no
// radix sort), the example of an orderer plugin. reverse=true sorts front to back, a wrong
// order the oracle must catch.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "harness/bench/plugin.h"

namespace {

class OotCentroid final : public vob::Orderer {
 public:
  explicit OotCentroid(bool reverse) : reverse_(reverse) {}
  vob::Claims claims() const override { return {}; }  // a heuristic

  void prepare(const vob::Scene& scene, vob::PhaseClock& clock) override {
    auto p = clock.phase("centroids");
    scene_ = scene;  // keeps the scene's cache (and its centroids) alive
    centroids_ = &scene_.cell_centroids().points;
  }

  vob::Ordering order(const vob::Camera& view, vob::PhaseClock& clock) override {
    auto p = clock.phase("sort");
    const auto& c = *centroids_;
    std::vector<double> key(c.size());
    for (size_t i = 0; i < c.size(); ++i) key[i] = vob::length(c[i] - view.eye);
    vob::Ordering out;
    out.order.resize(c.size());
    std::iota(out.order.begin(), out.order.end(), 0);
    std::stable_sort(out.order.begin(), out.order.end(), [&](int32_t a, int32_t b) {
      return reverse_ ? key[a] < key[b] : key[a] > key[b];
    });
    return out;
  }

  size_t bytes() const override { return 0; }

 private:
  bool reverse_;
  vob::Scene scene_;
  const std::vector<vob::Vec3>* centroids_ = nullptr;
};

}  // namespace

extern "C" void vobench_register_orderers(void) {
  vob::register_orderer(
      {"oot-centroid", vob::SceneKind::Cells,
       "out-of-tree plugin: cell centroids by eye distance, std::sort (heuristic)",
       {vob::ParamSpec::boolean("reverse", false, "front to back (wrong on purpose)")},
       [](const vob::ResolvedParams& p) -> std::unique_ptr<vob::Orderer> {
         return std::make_unique<OotCentroid>(p.get_bool("reverse"));
       }});
}
