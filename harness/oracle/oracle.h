// The z-buffer oracle (DESIGN.md "The oracle"). Draws the primitives in the given
// back-to-front order at the pixel centres (or S x S samples per pixel); per sample it keeps
// the nearest depth drawn so far; a fragment that lands behind it is a violation.
// Fragments (harness/raster): cells -> ray segment [t_in, t_out] at t >= 0 longer than
// oracle_min_segment (kMinSegmentRelative of the scene radius, more for a far eye;
// cell_clip.h); triangles -> hit depth at covered
// samples, top-left fill rule (polygon_raster.h); voxels -> splat footprint at the eye
// distance of the voxel centre (splat.h).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/oracle/rule_cycles.h"
#include "harness/raster/cell_clip.h"
#include "harness/raster/raster_rule.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct OracleOptions {
  int supersample = 1;          // S: S x S samples per pixel
  double splat_radius_px = 0;   // voxels: footprint radius in pixels; 0 = projected voxel size
  int max_examples = 5;         // violating fragments (and overlapping pairs) described
  bool violation_mask = false;  // fill OracleResult::violation_mask (costs w*h*S*S bytes)
  bool per_primitive = false;   // fill OracleResult::violating_fragments_per_primitive
  // The sampling rule (harness/raster/raster_rule.h). gl: llvmpipe's coverage at the pixel
  // centres, and triangle depths compared as a 24-bit depth test compares them.
  RasterRule raster = RasterRule::exact;
};

struct OracleResult {
  int supersample = 1;              // S
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
  // Cells only: distinct cell pairs whose segments overlap by more than half the shortest
  // kept segment (kOverlapRelative of the scene radius unless the eye is far) at some sample. Such cells interpenetrate: the input has no visibility
  // order, so their violations are the input's fault, not the orderer's.
  int64_t overlapping_pairs = 0;
  nlohmann::json overlap_examples = nlohmann::json::array();  // {cells, pixel, segments}
  // With OracleOptions::violation_mask: per pixel (index y * mask_width + x), 1 where any of
  // its S x S samples has a violating fragment; empty otherwise. At S = 1 the 1s number
  // exactly violating_pixels.
  std::vector<uint8_t> violation_mask;
  int mask_width = 0, mask_height = 0;
  // With OracleOptions::per_primitive: per primitive id (cells, triangles: all of them;
  // voxels: every voxel of the grid), its fragments that violated (the fragment drawn too
  // late is the one counted, as in violating_fragments, which these sum to). Empty otherwise.
  std::vector<int64_t> violating_fragments_per_primitive;
  // False for a verdict that has no primitive pairs (a compositing orderer's, orderer.h):
  // to_json then writes violating_pairs as null, not as a count of 0.
  bool pairs_counted = true;

  // gl rule, when the order violates: which violations lie on cycles of the rule's pixel
  // precedence graph, which every order must break (rule_cycles.h). An order whose only
  // violations are those, no more of them than the fewest any order has, is ok().
  std::optional<RuleCycles> rule_cycles;

  bool ok() const {
    return violating_fragments == 0 || (rule_cycles && rule_cycles->as_good_as_the_rule_allows());
  }
  bool input_fault() const { return overlapping_pairs > 0; }
  int64_t samples_with_k_above(int k) const;
  // Keys as everywhere: covered_pixels, violating_pixels, violating_fragments,
  // violating_pairs, max_k (plus fragments, max_list, k_histogram, examples, supersample,
  // overlapping_pairs and overlap_examples).
  nlohmann::json to_json() const;
};

// `order` lists primitive ids back to front (voxels: voxel ids of significant voxels).
// Ids missing from `order` are simply not drawn; out-of-range ids (and voxels that are not
// significant) throw InputError. An id listed twice is drawn twice (and then violates).
//
// Violation rules (k_metric.h counts k with the same comparisons, so k > 0 <=> violation):
// - cells: a fragment violates when its segment midpoint lies behind the nearest t_in drawn
//   so far at the sample. Segments of non-overlapping convex cells do not overlap, so the
//   midpoint separates them with a margin of half a segment (>= half the floor), far
//   above rounding noise.
// - triangles and voxels: a fragment violates when its depth exceeds the nearest depth drawn
//   so far by more than kDepthTieRelative * (scene radius + eye distance to its centre).
//   Equal depths (coplanar triangles, voxels at the same distance) are ties, not violations:
//   no order between them is more correct than another. Under the gl rule a triangle
//   fragment violates when its 24-bit window depth (raster_rule.h) exceeds the nearest
//   one's: what a GL depth test cannot tell apart is a tie.
// The blocking primitive of a violation is the one holding the nearest depth (or t_in).
// Overlap (cells): at every sample the segments, sorted by t_in, are swept for pairs that
// overlap by more than half the segment floor (kOverlapRelative * scene radius, or half
// kMinSegmentFarRelative of the largest t when the eye is more than about 100 radii away:
// t is known to about 1e-15 of itself, and an eye 1e9 away resolves it to 1e-7). Face
// neighbours compute the shared face's crossing from bit-identical planes (cell_clip.h), so their segments meet exactly;
// cells touching through duplicated nodes, an edge or a vertex meet within the rounding
// noise of t (about 1e-15 of the eye distance), the noise kMinSegmentRelative is set far
// above. The threshold is half the shortest kept segment because that is the smallest
// overlap that can make the midpoint rule flag an exact order (the front segment's
// midpoint must pass the back one's t_in): every overlap that can blame an orderer is
// reported, while staying 10^4 above the rounding noise of t at ordinary angles.
// (kOverlapRelative is defined with the cell model, harness/scene/cell_planes.h, which
// `vobench validate` applies to warped cells.)
// Samples are processed in bands of rows in parallel; results do not depend on threads.
constexpr double kDepthTieRelative = 1e-9;

OracleResult check_ordering(const Scene& scene, const Camera& view,
                            const std::vector<int32_t>& order, const OracleOptions& opt = {});

}  // namespace vob
