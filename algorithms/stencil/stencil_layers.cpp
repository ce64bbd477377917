#include "algorithms/stencil/stencil_layers.h"

#include <algorithm>
#include <memory>

#include "algorithms/stencil/layer_extraction.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

using namespace stencil;

class StencilLayers final : public Orderer {
 public:
  explicit StencilLayers(const ResolvedParams& p) : x_(p) {}

  Claims claims() const override {
    Claims c;
    c.image_exact = true;  // the GL backend under the gl sampling rule (what llvmpipe draws)
    if (x_.backend_name == "gl") c.image_exact_under = RasterRule::gl;
    c.detects_cycles = true;
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("upload triangles");
    const TriangleSoup& s = scene.soup();
    const size_t n = s.num_triangles();
    if (n >= size_t(INT32_MAX) - 1)
      throw InputError("stencil-layers", scene.name(), "too many triangles for 32-bit ids");
    points_.assign(4 * n, Vec3{});
    sizes_.assign(n, 3);
    centroids_.resize(n);
    for (size_t t = 0; t < n; ++t) {
      for (int k = 0; k < 3; ++k) points_[4 * t + k] = s.points[s.tris[t][k]];
      centroids_[t] = (points_[4 * t] + points_[4 * t + 1] + points_[4 * t + 2]) / 3.0;
    }
    x_.backend = make_layer_backend(x_.backend_name, "stencil-layers");
    x_.backend->set_primitives(points_, sizes_);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    {
      auto p = clock.phase("render");
      x_.backend->begin_frame(view);
    }
    const int32_t n = int32_t(sizes_.size());
    x_.extractor.run(*x_.backend, n, view, x_.opt, clock, x_.result);
    const LayerResult& result = x_.result;
    Ordering out;
    out.layers = result.layer;
    std::vector<int32_t> stuck, hidden;
    for (int32_t t = 0; t < n; ++t)
      if (result.layer[size_t(t)] < 0) (result.visible[size_t(t)] ? stuck : hidden).push_back(t);
    std::vector<std::pair<double, int32_t>> by_depth;
    for (int32_t t : stuck) by_depth.push_back({-view.depth(centroids_[size_t(t)]), t});
    std::sort(by_depth.begin(), by_depth.end());
    out.order.reserve(size_t(n));
    for (const auto& [d, t] : by_depth) out.order.push_back(t);
    out.order.insert(out.order.end(), hidden.begin(), hidden.end());
    // Layers back to front: counting sort by layer, farthest first.
    std::vector<int32_t> start(size_t(result.layers) + 1, 0);
    for (int32_t t = 0; t < n; ++t)
      if (result.layer[size_t(t)] >= 0) ++start[size_t(result.layers - 1 - result.layer[size_t(t)]) + 1];
    for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    const size_t base = out.order.size();
    out.order.resize(size_t(n));
    for (int32_t t = 0; t < n; ++t) {
      const int32_t l = result.layer[size_t(t)];
      if (l >= 0) out.order[base + size_t(start[size_t(result.layers - 1 - l)]++)] = t;
    }
    if (!stuck.empty()) out.cycles.add(stuck);
    for (int32_t t : result.forced) out.cycles.add({t});
    add_counters(out, result);
    out.counters["bytes_buffers"] = double(x_.extractor.bytes() + x_.backend->bytes());
    out.extras["footprint"] = result.footprint;
    out.extras["backend"] = x_.backend->name();
    return out;
  }

  size_t bytes() const override {
    return points_.capacity() * sizeof(Vec3) + sizes_.capacity() + centroids_.capacity() * sizeof(Vec3) +
           x_.bytes();
  }

  static void add_counters(Ordering& out, const LayerResult& r) {
    add_layer_counters(r, out);
    auto& k = out.counters;
    k["unclassified"] = double(r.unclassified_visible + r.unclassified_no_pixel);
    k["unclassified_visible"] = double(r.unclassified_visible);
    k["unclassified_no_pixel"] = double(r.unclassified_no_pixel);
  }

 private:
  Extraction x_;
  std::vector<Vec3> points_, centroids_;
  std::vector<int8_t> sizes_;
};

}  // namespace

OrdererInfo stencil_layers_orderer_info() {
  return extraction_orderer_info<StencilLayers>(
      "stencil-layers", SceneKind::Triangles,
      "Krishnan et al.'s layer extraction with item, z and stencil buffers (OpenGL through "
      "OSMesa, or the same passes on the harness rasterizer)");
}

}  // namespace vob
