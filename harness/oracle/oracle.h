// The z-buffer oracle (DESIGN.md "The oracle"). Draws the primitives in the given
// back-to-front order at the pixel centres (or S x S samples per pixel); per sample it keeps
// the nearest depth drawn so far; a fragment that lands behind it is a violation.
// Fragments: cells -> ray segment [t_in, t_out] of positive length; triangles -> hit depth;
// voxels -> splat footprint at the eye distance of the voxel centre.
#pragma once
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct OracleOptions {
  int supersample = 1;          // S: S x S samples per pixel
  double splat_radius_px = 0;   // voxels: footprint radius in pixels; 0 = projected voxel size
  int max_examples = 5;         // violating fragments described in the result
};

struct OracleResult {
  int64_t samples = 0;              // w*h*S*S
  int64_t fragments = 0;
  int64_t covered_pixels = 0;       // samples with at least one fragment
  int64_t violating_pixels = 0;     // samples with at least one violating fragment
  int64_t violating_fragments = 0;
  int64_t violating_pairs = 0;      // distinct (drawn-too-late, drawn-too-early) primitive pairs
  int max_k = 0;                    // largest displacement of a fragment from its sorted place
  int max_list = 0;                 // longest per-sample fragment list (HAVS "Max A")
  std::vector<int64_t> k_histogram;  // samples by their k (index = k)
  nlohmann::json examples = nlohmann::json::array();

  bool ok() const { return violating_fragments == 0; }
  int64_t samples_with_k_above(int k) const;
  // Keys as everywhere: covered_pixels, violating_pixels, violating_fragments,
  // violating_pairs, max_k (plus fragments, max_list, k_histogram, examples, supersample).
  nlohmann::json to_json() const;
};

// `order` lists primitive ids back to front (voxels: voxel ids of significant voxels).
// Ids missing from `order` are simply not drawn; out-of-range ids throw InputError.
OracleResult check_ordering(const Scene& scene, const Camera& view,
                            const std::vector<int32_t>& order, const OracleOptions& opt = {});

}  // namespace vob
