// The Orderer API: what every visibility-ordering plugin implements (DESIGN.md).
// prepare() does the view-independent work once per scene; order() runs per frame and
// returns a complete back-to-front permutation of the scene's primitives, even when the
// scene has a visibility cycle (the cycle is reported in the Ordering and broken).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/phase_clock.h"
#include "harness/oracle/oracle.h"
#include "harness/raster/raster_rule.h"
#include "harness/render/compositor.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct Claims {
  bool object_exact = false;  // exact for every ray (any resolution)
  bool image_exact = false;   // exact at the pixel centres of the view it was given
  // The sampling rule under which image_exact holds (harness/raster/raster_rule.h): gl for
  // what an OpenGL backend draws (llvmpipe's coverage and 24-bit depth), else exact.
  RasterRule image_exact_under = RasterRule::exact;
  bool detects_cycles = false;  // finds visibility cycles among the relations it builds
  // Composites its own image and fixes the order per pixel there (HAVS's k-buffer): it is
  // judged on what it composites (Orderer::composited_verdict), one verdict everywhere; the
  // oracle's count on its returned cell order is only the "derived cell order".
  bool composites = false;
  bool heuristic() const { return !object_exact && !image_exact; }
};

struct CycleReport {
  int64_t cycles = 0;                 // back edges met (each one broken)
  std::vector<int32_t> primitives;    // primitives involved (capped at kMaxReported)
  static constexpr size_t kMaxReported = 1000;
  void add(const std::vector<int32_t>& cycle_members);
};

struct Ordering {
  std::vector<int32_t> order;             // back-to-front primitive ids (voxels: voxel ids)
  CycleReport cycles;
  std::map<std::string, double> counters;  // plugin-specific counts (arrows, exact calls, ...)
  std::vector<int32_t> layers;            // optional: a layer per primitive (stencil)
  nlohmann::json extras;                  // optional plugin output
};

class Orderer {
 public:
  virtual ~Orderer() = default;
  // Name, scene kind and parameters live in the plugin's OrdererInfo (registry.h), not here.
  virtual Claims claims() const = 0;
  virtual void prepare(const Scene& scene, PhaseClock& clock) = 0;
  virtual Ordering order(const Camera& view, PhaseClock& clock) = 0;
  virtual size_t bytes() const = 0;         // memory the plugin holds after prepare/order
  // Only for Claims::composites: the verdict on what the last order() call (for `view`)
  // composited, with the oracle's conventions (pixel centres, S = 1, OracleResult's fields
  // where they have a meaning; with_mask fills violation_mask). The harness calls it
  // outside the PhaseClock phases, whenever a verdict is wanted (check; suites with the
  // oracle on), so it is never timed.
  virtual OracleResult composited_verdict(const Camera& view, bool with_mask);
  // Only for Claims::composites: the image the last order() (for `view`) composited and the
  // exact composite of the same fragments with the same shading (the reference of its
  // image error and difference image; the harness compositor shades differently).
  virtual void composited_images(const Camera& view, Image& composited, Image& exact);
};

}  // namespace vob
