#include "algorithms/stencil/stencil_xmpvo.h"

#include <algorithm>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/stencil/layer_extraction.h"

namespace vob {
namespace {

using namespace stencil;

class StencilXmpvo final : public Orderer {
 public:
  StencilXmpvo(std::string backend, ExtractOptions opt) : backend_name_(std::move(backend)), opt_(opt) {}

  Claims claims() const override {
    Claims c;
    c.image_exact = backend_name_ == "software";
    c.detects_cycles = true;
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    { auto p = clock.phase("unique faces"); scene.faces(); }
    { auto p = clock.phase("face planes"); scene.face_planes(); }
    core_.bind(scene);
    auto p = clock.phase("exterior face list");
    const MeshFaces& faces = core_.faces();
    const CellMesh& mesh = core_.scene().mesh();
    ext_face_ = faces.boundary;
    const size_t b = ext_face_.size();
    points_.assign(4 * b, Vec3{});
    sizes_.resize(b);
    cell_.resize(b);
    for (size_t i = 0; i < b; ++i) {
      const int32_t f = ext_face_[i];
      const int n = faces.face_size(f);
      for (int k = 0; k < n; ++k) points_[4 * i + k] = mesh.points[faces.face_points(f)[k]];
      sizes_[i] = int8_t(n);
      cell_[i] = faces.cell0[f];
    }
    backend_ = make_layer_backend(backend_name_, "stencil-xmpvo");
    backend_->set_primitives(points_, sizes_);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    const size_t b = ext_face_.size();
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
      front_.resize(b);
      for (size_t i = 0; i < b; ++i) front_[i] = core_.face_sign(ext_face_[i]) > 0;
    }
    {
      auto p = clock.phase("render");
      backend_->begin_frame(view);
      last_.assign(size_t(view.width) * view.height, 0);
      pairs_.clear();
    }
    int64_t pixel_pairs = 0;
    const PixelSink sink = [&](int64_t pixel, int32_t face, int) {
      const int32_t prev = last_[size_t(pixel)];
      last_[size_t(pixel)] = face + 1;
      if (prev && !front_[size_t(prev - 1)] && front_[size_t(face)]) {
        ++pixel_pairs;
        pairs_.push_back((uint64_t(uint32_t(cell_[size_t(prev - 1)])) << 32) | uint32_t(cell_[size_t(face)]));
      }
    };
    extractor_.run(*backend_, int32_t(b), view, opt_, clock, result_, &sink);
    {
      auto p = clock.phase("relations");
      std::sort(pairs_.begin(), pairs_.end());
      pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
      rel_.clear();
      rel_.reserve(pairs_.size());
      for (uint64_t k : pairs_) {
        const int32_t front = int32_t(k >> 32), behind = int32_t(k & 0xffffffffu);
        if (front != behind) rel_.push_back({front, behind});
      }
      extra_.build_from_pairs(core_.num_cells(), rel_);
    }
    {
      auto p = clock.phase("DFS");
      core_.dfs_all(out, &extra_);
    }
    core_.add_counters(out);
    auto& k = out.counters;
    k["layers"] = result_.layers;
    k["candidate_passes"] = double(result_.candidate_passes);
    k["complexity_passes"] = double(result_.complexity_passes);
    k["passes"] = double(result_.candidate_passes + result_.complexity_passes);
    k["reads"] = double(result_.reads);
    k["pixels_read"] = double(result_.pixels_read);
    k["blocks_read"] = double(result_.blocks_read);
    k["covered_pixels"] = double(result_.covered_pixels);
    k["average_depth_complexity"] = result_.average_depth_complexity();
    k["max_stencil"] = result_.max_stencil;
    k["removals"] = double(result_.removals);
    k["uncovered_removals"] = double(result_.uncovered_removals);
    k["tie_pixels"] = double(result_.tie_pixels);
    k["forced"] = double(result_.forced.size());
    k["exterior_faces"] = double(b);
    k["pixel_pairs"] = double(pixel_pairs);
    k["relations"] = double(rel_.size());
    k["unclassified_faces"] = double(result_.unclassified_visible);
    k["unclassified_no_pixel"] = double(result_.unclassified_no_pixel);
    k["bytes_pixels"] = double(last_.capacity() * 4 + extractor_.bytes() + backend_->bytes());
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + points_.capacity() * sizeof(Vec3) + sizes_.capacity() +
           (cell_.capacity() + ext_face_.capacity() + last_.capacity()) * 4 + front_.capacity() +
           pairs_.capacity() * 8 + rel_.capacity() * 8 + extra_.bytes() + extractor_.bytes() +
           (backend_ ? backend_->bytes() : 0) + result_.layer.capacity() * 4 + result_.visible.capacity();
  }

 private:
  std::string backend_name_;
  ExtractOptions opt_;
  mpvo::MpvoCore core_;
  std::vector<int32_t> ext_face_, cell_;
  std::vector<Vec3> points_;
  std::vector<int8_t> sizes_;
  std::vector<uint8_t> front_;
  std::vector<int32_t> last_;  // per pixel: exterior face seen in the latest layer + 1
  std::vector<uint64_t> pairs_;
  std::vector<std::pair<int32_t, int32_t>> rel_;
  mpvo::ExtraRelations extra_;
  std::unique_ptr<LayerBackend> backend_;
  LayerExtractor extractor_;
  LayerResult result_;
};

}  // namespace

OrdererInfo stencil_xmpvo_orderer_info() {
  return {"stencil-xmpvo", SceneKind::Cells,
          "Krishnan et al.'s discretized XMPVO: exterior faces layered with the stencil "
          "buffer, relations between faces met at a pixel in consecutive layers, MPVO DFS",
          stencil::extraction_params(),
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<StencilXmpvo>(p.get_choice("backend"), stencil::extract_options(p));
          }};
}

}  // namespace vob
