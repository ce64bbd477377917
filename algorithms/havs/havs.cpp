#include "algorithms/havs/havs.h"

#include <algorithm>

#include "algorithms/havs/face_bins.h"
#include "algorithms/havs/gl/gl_kbuffer.h"
#include "algorithms/havs/havs_frame.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

// The one verdict of HAVS (Claims::composites): what its k-buffer composited, with the
// oracle's conventions (pixel centres, S = 1, mask and counts per pixel). How HAVS's rule
// maps onto the oracle's fragment rule: the oracle draws cell segments in the given order
// and flags a segment that lands behind the nearest one drawn so far, i.e. one that would be
// composited out of order. HAVS composites the segments itself, one per pair of entries
// leaving its k-buffer; the exact composite is the consecutive pairs of the pixel's
// fragments sorted by depth (the A-buffer). A composited segment violates when it is not
// the exact sequence's segment at the same position ("the segment sequence differs from the
// exact sorted one"), so violating_fragments counts such segments, violating_pixels the
// pixels with at least one, and an exact composite has none, as an exact order has none
// for the oracle. fragments / max_list count face fragments (what HAVS sorts), not cell
// segments; max_k and k_histogram are the oracle's k on that face stream (positions a
// fragment is out of its sorted place = havs k_needed - 1; uncovered pixels at k = 0);
// there are no primitive pairs (violating_pairs: null).
OracleResult verdict_of(const havs::Analysis& a, int width, int height, bool with_mask) {
  OracleResult r;
  r.supersample = 1;
  r.samples = int64_t(width) * height;
  r.fragments = a.fragments;
  r.covered_pixels = a.covered_pixels;
  r.violating_pixels = a.violating_pixels;
  r.violating_fragments = a.violating_segments;
  r.pairs_counted = false;
  r.max_list = a.max_list;
  r.k_histogram.assign(std::max<size_t>(1, a.k_histogram.empty() ? 1 : a.k_histogram.size() - 1), 0);
  r.k_histogram[0] = r.samples - a.covered_pixels;
  for (size_t need = 1; need < a.k_histogram.size(); ++need) r.k_histogram[need - 1] += a.k_histogram[need];
  r.max_k = std::max(0, a.max_k_needed - 1);
  constexpr int kExamples = 5;  // as OracleOptions::max_examples
  for (size_t p = 0; p < a.violating.size() && r.examples.size() < kExamples; ++p)
    if (a.violating[p]) r.examples.push_back({{"pixel", {int(p % width), int(p / width)}}});
  if (with_mask) {
    r.violation_mask = a.violating;
    r.mask_width = width;
    r.mask_height = height;
  }
  return r;
}

class HavsOrderer final : public Orderer {
 public:
  HavsOrderer(int k, bool analyze, std::string backend, std::string gl_draw)
      : k_(k), analyze_(analyze), backend_(std::move(backend)), gl_draw_(std::move(gl_draw)) {}
  Claims claims() const override {
    Claims c;
    c.composites = true;
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    auto p = clock.phase("faces");
    fd_ = havs::build_face_data(scene);
    analyzed_view_.clear();
    ordered_view_.clear();
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
    ordered_view_.clear();  // set after the timed phases (the key costs a JSON dump)
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
        rs = havs::render_kbuffer(fd_, view, face_order_, k_, image_, &bins_);
      }
    }
    // Harness bookkeeping, untimed: the cell permutation and the error analysis.
    Ordering out;
    ordered_view_ = view.to_json().dump();
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
      const havs::Analysis& a = analysis(view);
      out.counters.insert({{"havs_max_list", a.max_list},
                           {"havs_max_k_needed", a.max_k_needed},
                           {"havs_pixels_k_gt_2", double(a.pixels_k_above(2))},
                           {"havs_pixels_k_gt_6", double(a.pixels_k_above(6))},
                           {"havs_covered_pixels", double(a.covered_pixels)},
                           {"havs_violating_pixels", double(a.violating_pixels)},
                           {"havs_violating_segments", double(a.violating_segments)},
                           {"havs_image_rmse", a.image_error.rmse},
                           {"havs_image_max_error", a.image_error.max_error},
                           {"havs_pixels_off", double(a.image_error.pixels_off)}});
    }
    return out;
  }

  // backend=gl: the verdict is the software k-buffer's on the same face order (analyze
  // reruns it); the shader's image equals it up to llvmpipe's rasterization rounding
  // (tests/algorithms/havs/havs_gl_test.cpp: at most 1% of pixels differ, race-free draws).
  OracleResult composited_verdict(const Camera& view, bool with_mask) override {
    const havs::Analysis& a = analysis(view);
    return verdict_of(a, view.width, view.height, with_mask);
  }

  // The image is the one the timed k-buffer phase made (backend=gl: the shader's), when the
  // view is the last order()'s; the exact one is the A-buffer composite of the same fragments.
  void composited_images(const Camera& view, Image& composited, Image& exact) override {
    const havs::Analysis& a = analysis(view);
    composited = view.to_json().dump() == ordered_view_ ? image_ : a.kbuffer_image;
    exact = a.exact_image;
  }

  size_t bytes() const override {
    return fd_.bytes() + sort_.bytes() + face_order_.capacity() * 4 + image_.rgb.capacity() * 4 +
           bins_.bytes() + (gl_ ? gl_->bytes() : 0);
  }

 private:
  int k_;
  bool analyze_;
  std::string backend_, gl_draw_;
  havs::FaceData fd_;
  std::unique_ptr<havs::GlKBuffer> gl_;  // backend=gl; refers to fd_
  int gl_draws_ = 0;
  havs::SortBuffers sort_;
  havs::FaceBins bins_;  // the k-buffer pass' binning buffers, kept from frame to frame
  std::vector<int32_t> face_order_;
  Image image_;
  // The analysis of the last order()'s face order, per view: deterministic, so repeats of
  // one view, the verdict and the images share it. Untimed, and not counted in bytes().
  const havs::Analysis& analysis(const Camera& view) {
    const std::string key = view.to_json().dump();
    if (key != analyzed_view_) {
      if (key != ordered_view_) havs::sort_faces(fd_, view, sort_, face_order_);
      analysis_ = havs::analyze(fd_, view, face_order_, k_);
      analyzed_view_ = key;
    }
    return analysis_;
  }
  std::string analyzed_view_, ordered_view_;
  havs::Analysis analysis_;
};

}  // namespace

OrdererInfo havs_orderer_info() {
  return {"havs", SceneKind::Cells,
          "HAVS (Callahan et al.): face centroid radix sort + software k-buffer (heuristic; "
          "judged on what it composites)",
          {ParamSpec::integer("k", 2, 1, havs::kMaxK, "k-buffer entries per pixel (the paper's hardware: 2 or 6)"),
           ParamSpec::boolean("analyze", true, "the havs_* counters of the per-pixel analysis (untimed; the verdict runs it anyway)"),
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
