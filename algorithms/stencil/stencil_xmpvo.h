// Plugin `stencil-xmpvo` (cells): the discretized XMPVO of Krishnan, Silva and Wei (2001,
// section 4) on MpvoCore. The exterior (boundary) faces of the mesh are layered with the
// stencil layer extraction (layer_extraction.h); every pixel records which face it saw in
// each layer, and two faces met at the same pixel in consecutive layers, the nearer
// back-facing (the ray leaves the mesh) and the farther front-facing (it enters again),
// give the relation "the farther face's cell is behind the nearer face's cell". The
// relations (deduplicated) join the MPVO face arrows, and the MPVO DFS sorts the cells.
//
// Parameters: those of stencil-layers (stencil::extraction_params()).
//
// A layer's faces are front-most wherever they cover a pixel, so at every pixel the faces
// come in depth order, one per layer: the pairs are those of an A-buffer of exterior faces
// at pixel centres (Cook et al.'s SXMPVO pairs the same consecutive entries), one ray per
// pixel as the paper says.
//
// Prepare: "unique faces", "face planes", "exterior faces" (the Scene's: boundary faces and
// owner cells), "upload" (to the backend).
// Phases: "I create partial order" (MPVO arrows), "render", "read", "scan" (layer
// extraction; the scan also records the pixel pairs), "relations" (deduplicate, CSR),
// "DFS".
// Counters: MpvoCore's (exact_sign_calls, double_sign_wrong, arrows, sink_cells,
// cycle_roots), the layer extraction's (layers, passes, reads, pixels_read, blocks_read,
// covered_pixels, fragments, average_depth_complexity, max_stencil, removals,
// uncovered_removals, tie_pixels, forced; see stencil-layers), exterior_faces, pixel_pairs (back/front pairs met at
// pixels), relations (distinct cell pairs), unclassified_faces (covered a pixel but never
// layered: their pixels lose relations), unclassified_no_pixel, bytes_pixels.
//
// Claims: software: image_exact when every visible exterior face gets a layer (an
// exterior-face visibility cycle leaves faces unclassified, counted above), detects_cycles.
// gl: heuristic (llvmpipe's pixel centres can differ from the oracle's at edges and
// near-equal depths), detects_cycles.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo stencil_xmpvo_orderer_info();
}  // namespace vob
