// Krishnan, Silva and Wei's layer extraction (section 3, steps 1 to 5) over a LayerBackend.
//
// While T (the unclassified primitives) is not empty:
//   1-2. candidate pass: render T (ascending ids) with GL_LESS, depth cleared to 1.0,
//        stencil disabled;
//   3.   read the item buffer C; F = every primitive seen in it (the candidates);
//   4.   do: render F (descending ids) with GL_GEQUAL, depth cleared to 0.0, stencil GL_INCR;
//        read the item buffer G (the farthest F primitive per pixel) and the stencil S (the
//        depth complexity of F); remove from F the primitive G(p) at every pixel p with
//        G(p) != C(p);
//        while another pass can still remove something;
//        T_i = F, i += 1;
//   5.   stop when a round classifies nothing: the rest are unclassified (or, with
//        break_cycles, force the candidate front-most at the most pixels into a layer).
//
// Where we differ from the paper's wording, and why:
// - Removal test. The paper removes G(p) where S(p) > 1. That misses one case: when a
//   candidate W is removed because it lies behind another candidate at some pixel, a
//   candidate X that lay behind W at a different pixel p (behind W and in front of a third
//   one there, so not itself the farthest at p) can end alone at p and is kept, although W,
//   still in T, is in front of it; X then gets a lower layer than W and the back-to-front
//   order draws W before X (a test builds this scene). C(p) is the front-most primitive of
//   T at p, so "G(p) != C(p)" removes exactly the primitives that something in T covers:
//   with S(p) > 1 it is the paper's test (the farthest of several is not the nearest); with
//   S(p) = 1 it catches the case above. Pixels where G(p) == C(p) although S(p) > 1 are
//   depth ties (GEQUAL keeps the last drawn, LESS the first, and F is drawn in the opposite
//   order of T); they remove nothing, as the oracle treats equal depths as ties.
// - Early exit. The paper leaves the loop when no pixel has S > 2. Here: after a pass's
//   removals the layer is final when no pixel has S >= 3 and every pixel with S == 2 still
//   had its C(p) in F (then the one left there is C(p)); otherwise one more pass.
// - Footprint. After a layer is final, its pixels are those where C(p) is in the layer
//   (a layer's primitives are front-most wherever they are); an optional sink sees every
//   (pixel, primitive, layer), in layer order, which is what stencil-xmpvo needs.
//
// Variants: naive reads and scans the whole buffers at every pass; blocked divides the
// image into B x B blocks and, as the paper proposes, reads and scans only blocks that can
// still be covered: a block with no covered pixel after a candidate pass stays empty for
// the rest of the frame (T only shrinks), and within step 4 a block where F covered nothing
// stays empty too (F only shrinks).
//
// Phases: "render" (drawing, including the wait for completion), "read", "scan".
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "algorithms/stencil/layer_backend.h"
#include "harness/bench/orderer.h"
#include "harness/bench/param_spec.h"
#include "harness/bench/registry.h"
#include "harness/bench/phase_clock.h"

namespace vob::stencil {

struct ExtractOptions {
  bool blocked = false;
  int block = 64;  // pixels per block side (blocked)
  // Step 5 finds a round that classifies nothing (a visibility cycle among the candidates,
  // or one made by the backend's depth rounding). false: stop there, as the paper does;
  // the rest stays unclassified. true: break the cycle by giving one candidate of that
  // round a layer of its own, and go on: the one seen behind another candidate at the
  // fewest pixels (G(p) != C(p)), of those the one front-most at the most pixels.
  bool break_cycles = false;
};

// The parameters stencil-layers and stencil-xmpvo share (backend, variant, block, cycles),
// declared once for both registrations, and the options they resolve to.
std::vector<ParamSpec> extraction_params();
ExtractOptions extract_options(const ResolvedParams& p);

struct LayerResult {
  std::vector<int32_t> layer;           // per primitive: layer (0 = front) or -1
  std::vector<uint8_t> visible;         // per primitive: ever a candidate (covered a pixel)
  int layers = 0;
  std::vector<int64_t> footprint;       // pixels per layer
  int64_t candidate_passes = 0, complexity_passes = 0;
  int64_t reads = 0;                    // glReadPixels calls (colour and stencil)
  int64_t pixels_read = 0;              // pixels transferred, summed over buffers
  int64_t blocks_read = 0;              // block reads (blocked), colour and stencil counted once
  int64_t covered_pixels = 0;           // pixels covered by any primitive (first candidate pass)
  int64_t fragments = 0;                // sum of the footprints: classified primitives' pixels
  int64_t removals = 0;                 // candidates sent back to T
  int64_t uncovered_removals = 0;       // of which at S(p) == 1 (the case the paper misses)
  int64_t tie_pixels = 0;               // pixels with S > 1 and G == C
  int max_stencil = 0;
  std::vector<int32_t> forced;          // break_cycles: the primitive forced in each stuck round
  int64_t unclassified_visible = 0;     // covered some pixel but never got a layer (cycles)
  int64_t unclassified_no_pixel = 0;    // covered no pixel centre (edge-on, tiny, out of view)
  double average_depth_complexity() const {
    return covered_pixels ? double(fragments) / double(covered_pixels) : 0.0;
  }
};

// The extraction's counters common to both stencil plugins (layers, passes, reads, pixels,
// depth complexity, removals, ties, forced rounds) into out.counters.
void add_layer_counters(const LayerResult& r, Ordering& out);

// (pixel index y * W + x, primitive, layer), called for every pixel of every final layer.
using PixelSink = std::function<void(int64_t, int32_t, int)>;

class LayerExtractor {
 public:
  // Extracts the layers of primitives [0, n) at `view` (the backend has them and the frame
  // begun). `sink` may be null.
  void run(LayerBackend& backend, int32_t n, const Camera& view, const ExtractOptions& opt,
           PhaseClock& clock, LayerResult& out, const PixelSink* sink = nullptr);
  size_t bytes() const;

 private:
  void read_blocks(LayerBackend& backend, const std::vector<int32_t>& blocks, bool stencil,
                   LayerResult& out);
  PixelRect block_rect(int32_t b) const;

  int w_ = 0, h_ = 0, bw_ = 1, bh_ = 1, block_ = 0;
  bool whole_ = true;
  std::vector<uint32_t> cand_, far_;  // C and G
  std::vector<uint8_t> stencil_;      // S
  std::vector<int32_t> t_, f_, f0_, draw_, active_, f_blocks_, next_;
  std::vector<int32_t> front_pixels_;   // per primitive: pixels where it is C(p) this round
  std::vector<int32_t> behind_pixels_;  // per primitive: pixels where it was G(p) != C(p)
  std::vector<int32_t> blocker_;        // per primitive: a C(p) it was found behind, or -1
  std::vector<int32_t> cycle_;          // scratch: a cycle of blockers in a stuck round
  int32_t forced_candidate();          // the candidate a stuck round forces
  std::vector<uint8_t> in_f_;  // 1 in F, 2 removed in the current pass, 0 otherwise (3: met by forced_candidate's walk)
};

// What both stencil plugins hold: the backend they were asked for, the extraction options
// (both from extraction_params()), the backend once made, and the extractor with its
// latest result.
struct Extraction {
  explicit Extraction(const ResolvedParams& p)
      : backend_name(p.get_choice("backend")), opt(extract_options(p)) {}
  std::string backend_name;
  ExtractOptions opt;
  std::unique_ptr<LayerBackend> backend;
  LayerExtractor extractor;
  LayerResult result;
  size_t bytes() const;  // extractor, backend and the result's per-primitive arrays
};

// The registration of a stencil plugin: its parameters are extraction_params(), and
// `Plugin` is constructed from the resolved ones.
template <class Plugin>
OrdererInfo extraction_orderer_info(std::string name, SceneKind kind, std::string doc) {
  return {std::move(name), kind, std::move(doc), extraction_params(),
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> { return std::make_unique<Plugin>(p); }};
}

}  // namespace vob::stencil
