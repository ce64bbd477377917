#include "algorithms/havs/havs.h"

#include "algorithms/havs/gl/gl_kbuffer.h"
#include "algorithms/havs/havs_frame.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

class HavsOrderer final : public Orderer {
 public:
  HavsOrderer(int k, bool analyze, std::string backend, std::string gl_draw)
      : k_(k), analyze_(analyze), backend_(std::move(backend)), gl_draw_(std::move(gl_draw)) {}
  Claims claims() const override { return {}; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("faces");
    fd_ = havs::build_face_data(scene);
    if (backend_ == "gl") {
      gl_.reset();
      try {
        gl_ = std::make_unique<havs::GlKBuffer>(fd_);
      } catch (const havs::GlUnavailable& e) {
        throw InputError("havs", "backend=gl", e.what());
      }
    }
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    {
      auto p = clock.phase("cpu sort");
      havs::sort_faces(fd_, view, sort_, face_order_);
    }
    havs::RenderStats rs;
    {
      auto p = clock.phase("k-buffer");
      if (gl_) {
        const havs::GlFrameStats g = gl_->render(
            view, face_order_, k_,
            gl_draw_ == "serialized" ? havs::GlDrawMode::Serialized : havs::GlDrawMode::Batched, image_);
        rs.fragments = g.fragments;
        gl_draws_ = g.draws;
      } else {
        rs = havs::render_kbuffer(fd_, view, face_order_, k_, image_);
      }
    }
    // Harness bookkeeping, untimed: the cell permutation and the error analysis.
    Ordering out;
    out.order = havs::cell_order_from_faces(fd_, face_order_);
    out.counters["havs_fragments"] = double(rs.fragments);
    if (gl_) {
      out.counters["havs_gl_fragments"] = double(rs.fragments);
      out.counters["havs_gl_draws"] = double(gl_draws_);
    } else {
      out.counters["havs_segments"] = double(rs.segments);
    }
    out.counters["havs_faces"] = double(face_order_.size());
    if (analyze_) {
      const std::string key = view.to_json().dump();
      if (key != analyzed_view_) {
        const havs::Analysis a = havs::analyze(fd_, view, face_order_, k_);
        counters_ = {{"havs_max_list", a.max_list},
                     {"havs_max_k_needed", a.max_k_needed},
                     {"havs_pixels_k_gt_2", double(a.pixels_k_above(2))},
                     {"havs_pixels_k_gt_6", double(a.pixels_k_above(6))},
                     {"havs_covered_pixels", double(a.covered_pixels)},
                     {"havs_violating_pixels", double(a.violating_pixels)},
                     {"havs_violating_segments", double(a.violating_segments)},
                     {"havs_image_rmse", a.image_error.rmse},
                     {"havs_image_max_error", a.image_error.max_error},
                     {"havs_pixels_off", double(a.image_error.pixels_off)}};
        analyzed_view_ = key;
      }
      for (const auto& [name, v] : counters_) out.counters[name] = v;
    }
    return out;
  }

  size_t bytes() const override {
    return fd_.bytes() + sort_.bytes() + face_order_.capacity() * 4 + image_.rgb.capacity() * 4 +
           (gl_ ? gl_->bytes() : 0);
  }

 private:
  int k_;
  bool analyze_;
  std::string backend_, gl_draw_;
  havs::FaceData fd_;
  std::unique_ptr<havs::GlKBuffer> gl_;  // backend=gl; refers to fd_
  int gl_draws_ = 0;
  havs::SortBuffers sort_;
  std::vector<int32_t> face_order_;
  Image image_;
  std::string analyzed_view_;
  std::map<std::string, double> counters_;
};

}  // namespace

OrdererInfo havs_orderer_info() {
  return {"havs", SceneKind::Cells,
          "HAVS (Callahan et al.): face centroid radix sort + software k-buffer (heuristic; its "
          "per-pixel error is in the havs_* counters)",
          {ParamSpec::integer("k", 2, 1, havs::kMaxK, "k-buffer entries per pixel (the paper's hardware: 2 or 6)"),
           ParamSpec::boolean("analyze", true, "measure against the exact per-pixel order (untimed)"),
           ParamSpec::choice("backend", "software", {"software", "gl"},
                             "software k-buffer, or the OpenGL fragment-shader k-buffer on OSMesa"),
           ParamSpec::choice("gl_draw", "batched", {"batched", "serialized"},
                             "gl only: one draw call, or race-free runs separated by memory barriers")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<HavsOrderer>(p.get_int("k"), p.get_bool("analyze"),
                                                 p.get_choice("backend"), p.get_choice("gl_draw"));
          }};
}

}  // namespace vob
