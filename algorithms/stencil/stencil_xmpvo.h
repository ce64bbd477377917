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
// gl: image_exact under the gl sampling rule (claims.image_exact_under: what llvmpipe draws,
// harness/raster/raster_rule.h; cells: cell_raster_gl.h), detects_cycles. MPVO's arrows and
// the exterior faces' facing follow the winding of the snapped faces (snapped_signs.h), and
// a back/front pixel pair is kept only where the rule orders the two faces the same way
// (llvmpipe's float depth interpolation can order two faces that meet at a pixel centre;
// coplanar faces of touching volumes are paired back face first). Exterior faces with the
// same points (touching volumes meshed with duplicated nodes) are not layered: they are a
// shared face, related as MPVO relates one (counter coincident_face_pairs); layered, their
// 24-bit ties made cycles the scene does not have. The claim is for the snapped mesh: where
// snapping inverts cells thinner than its 1/256-pixel grid (small images of slivers, of the
// non-conforming touching-* cases) the snapped cells overlap, no order of them is exact,
// and `check --raster gl` exits 2 naming the snapped mesh, as for any input without a
// visibility order.
// Counters (gl): snapped_sign_flips, dropped_pairs, swapped_pairs.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo stencil_xmpvo_orderer_info();
}  // namespace vob
