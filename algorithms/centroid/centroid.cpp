#include "algorithms/centroid/centroid.h"

#include <algorithm>
#include <type_traits>

#include "algorithms/centroid/centroid_keys.h"
#include "algorithms/centroid/key_order.h"

namespace vob {
namespace {

class CentroidOrderer final : public Orderer {
 public:
  explicit CentroidOrderer(bool view_key) : view_key_(view_key) {}
  Claims claims() const override { return {}; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("centroids");
    const std::vector<Vec3>& c = scene.cell_centroids().points;
    const size_t n = c.size(), k = RadixArgsort::kSample;
    // Three float arrays relative to the centroids' box centre, not Vec3s: the key pass then
    // loads whole vectors (AVX2: 4 cells a step) and streams 12 bytes a cell instead of 24
    // (centroid_keys.h). Every kSample-th centroid also in a compact copy: the key pass's
    // sample of the buckets reads 0.4 MB in a row instead of one cache line per sample.
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Vec3& q : c)
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
    origin_ = n ? (lo + hi) * 0.5 : Vec3{};
    for (auto* v : {&xs_, &ys_, &zs_}) v->resize(n);
    for (auto* v : {&sxs_, &sys_, &szs_}) v->resize((n + k - 1) / k);
    lo_ = {1e300, 1e300, 1e300}, hi_ = {-1e300, -1e300, -1e300};  // of the stored centroids
    for (size_t i = 0; i < n; ++i) {
      const Vec3 d = c[i] - origin_;
      xs_[i] = static_cast<float>(d.x), ys_[i] = static_cast<float>(d.y), zs_[i] = static_cast<float>(d.z);
      if (i % k == 0) sxs_[i / k] = xs_[i], sys_[i / k] = ys_[i], szs_[i / k] = zs_[i];
      const Vec3 stored{xs_[i], ys_[i], zs_[i]};
      for (int a = 0; a < 3; ++a) lo_[a] = std::min(lo_[a], stored[a]), hi_[a] = std::max(hi_[a], stored[a]);
    }
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    const Vec3 f = view.forward();
    const bool by_view = view_key_ || view.ortho;  // orthographic: eye distance is view depth
    const Vec3 eye = view.eye - origin_;             // in the stored centroids' frame
    const size_t n = xs_.size();
    const KeyRange r = key_range_from_box(lo_, hi_, eye, f, by_view);
    const bool guess = r.lo <= r.hi;  // -key ascending: r.hi gives the least sortable bits
    const uint32_t lo = guess ? descending_key_bits(r.hi) : 1u, hi = guess ? descending_key_bits(r.lo) : 0u;
    const CentroidArrays a{xs_.data(), ys_.data(), zs_.data()}, s{sxs_.data(), sys_.data(), szs_.data()};
    // Two instantiations rather than a test per cell; the keys are the same doubles as Vec3's
    // dot and length give of the stored centroids (centroid_keys.h).
    const auto with = [&](auto by) {
      constexpr bool kByView = decltype(by)::value;
      const auto key = [=](size_t i) { return centroid_key<kByView>(a, eye, f, i); };
      const auto sample = [=](size_t j) { return centroid_key<kByView>(s, eye, f, j); };
      const CentroidKeyRun run = centroid_key_run(kByView);
      const auto keys = [=](size_t i0, size_t i1, uint32_t* k) { run(a, eye, f, i0, i1, k); };
      return order_from_key_pass(n, [&] { sort_.make_keys_by_runs(n, key, keys, sample, lo, hi); }, sort_, clock);
    };
    return by_view ? with(std::true_type{}) : with(std::false_type{});
  }

  size_t bytes() const override {
    return (xs_.capacity() + ys_.capacity() + zs_.capacity() + sxs_.capacity() + sys_.capacity() +
            szs_.capacity()) * sizeof(float) + sort_.bytes();
  }

 private:
  bool view_key_;
  Vec3 origin_;                         // the centroids' box centre
  std::vector<float> xs_, ys_, zs_;     // centroid - origin_ (view-independent, as VTK's cell centres)
  std::vector<float> sxs_, sys_, szs_;  // every RadixArgsort::kSample-th of them
  Vec3 lo_{1e300, 1e300, 1e300}, hi_{-1e300, -1e300, -1e300};  // the stored centroids' box
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
