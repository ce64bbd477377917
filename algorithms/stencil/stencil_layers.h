// Plugin `stencil-layers` (triangles): Krishnan, Silva and Wei's hardware-assisted
// visibility ordering (2001, section 3): layers extracted with an item buffer, the z-buffer
// and the stencil buffer (layer_extraction.h), front to back; the Ordering is back to front.
//
// Parameters backend, variant, block, cycles: declared once for both stencil plugins in
// stencil::extraction_params() (layer_extraction.cpp); beyond their one-line docs:
//   backend  gl: gl_backend.h; software: software_backend.h
//   cycles   a round that classifies nothing (a visibility cycle, or one made by
//            the backend's depth rounding at silhouettes) either forces one
//            candidate (seen behind others at the fewest pixels) into a layer of
//            its own and goes on (break), or ends the extraction as the paper's
//            step 5 does (stop), leaving the rest unclassified
//
// Ordering: order = unclassified primitives first (those that covered a pixel but never
// got a layer, far to near by centroid distance, then those that covered no pixel centre),
// then the layers from the last (farthest) to layer 0, ascending ids within a layer;
// layers = the layer of every triangle (0 = front), -1 when unclassified. Unclassified
// triangles that covered a pixel (a visibility cycle, or behind one; cycles=stop) are
// reported as one cycle in Ordering::cycles; with cycles=break every forced triangle is
// reported as a cycle of its own.
// Phases: "render", "read", "scan" (the paper's reading and scanning).
// Counters: layers, candidate_passes, complexity_passes, passes, reads, pixels_read,
// blocks_read, covered_pixels, fragments (pixels of classified triangles),
// average_depth_complexity (fragments / covered_pixels), max_stencil, removals,
// uncovered_removals (removals at stencil 1, the case the paper's test misses; see
// layer_extraction.h), tie_pixels, forced (cycles broken), unclassified, unclassified_visible,
// unclassified_no_pixel, bytes_buffers. Extras: footprint (pixels per layer), backend.
//
// Claims: software: image_exact (exact at the pixel centres of the view for scenes without
// visibility cycles: every layer is front-most wherever it covers a pixel centre, with the
// oracle's rasterizer) and detects_cycles. gl: image_exact under the gl sampling rule
// (claims.image_exact_under "gl": llvmpipe's 1/256-pixel snapping, fill rule and 24-bit
// depth, harness/raster/raster_rule.h; `vobench check --raster gl`), detects_cycles.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo stencil_layers_orderer_info();
}  // namespace vob
