// Plugin `sxmpvo`: Cook, Max, Silva and Williams' Scanning Exact Meshed Polyhedra
// Visibility Ordering (IEEE TVCG 2004, sections 4 and 5), on MpvoCore.
//
// sxmpvo    renumber=true curve=hilbert keep_coherent=true: cells and points renumbered in
//           prepare when the curve is more coherent than the input's numbering, as mpvo
//           (mpvo.h); orders and cycle reports are in input ids. The image resolution is the view's viewport; samples are the
//           pixel centres of the shared rasterizer (harness/raster/polygon_raster.h, S = 1),
//           the same samples the oracle checks at its default S = 1.
//
// Prepare: ["renumber along a space curve"], "unique faces", "face planes", "exterior faces" (the Scene's: per boundary face
// its points, compact point ids and owner), "exterior centroids".
// Phases, under the paper's names:
//   "I create partial order"  MPVO face arrows and outbound counts (the sink flags);
//   "II sort exterior faces"  every exterior face by increasing centroid distance from the
//       eye (depth along the view direction for orthographic views), LSD radix sort;
//   "III scan faces and add dependencies"  exterior faces scan-converted into per-pixel PIX
//       lists kept in decreasing depth by insertion in the sorted order (faces are scanned
//       in storage order and their entries replayed by rank; triangles covering a few
//       samples take the path of tiny_faces.h, the same samples and depths); consecutive front-facing
//       (farther) / back-facing (nearer) entries form pseudo-neighbour relations, stored in
//       the occluding cell's PN list without duplicates (move-to-front search); the lists
//       become MpvoCore extra relations, and occluded cells lose their sink flag;
//   "IV DFS"  DFS from every sink cell with PN neighbours eligible, then from cells left
//       unvisited by cycles (reported in Ordering::cycles and broken).
// Ties: entries within 1e-9 * (scene radius + eye distance to the box centre) of each other
// may be reordered within the tie to restore the back/front alternation of a closed
// boundary (touching faces, rays through silhouette edges); see abuffer.h.
//
// Claims: image_exact (exact at the pixel centres of the view given, for acyclic meshes),
// detects_cycles. Not object_exact: ray gaps between pixel centres are not sampled.
// Counters: MpvoCore's (exact_sign_calls, double_sign_wrong, arrows, sink_cells,
// cycle_roots), exterior_faces, tiny_path_faces (faces scanned by tiny_faces.h), abuffer_entries (Cook's a at this view), head_insertions,
// head_insertion_rate, insertion_walk_steps, pix_lists, max_pix_list, pn_pairs (pairs found
// in PIX lists), pn_relations (distinct PN entries), pn_found_at_head, pn_moved_to_front,
// pn_search_steps, tie_reorders, unpaired_entries, self_pairs, and memory in bytes:
// bytes_mpvo (MpvoCore's arrays), bytes_faces (unique faces and planes, shared with MPVO),
// bytes_abuffer, bytes_pn (PN lists and their CSR), bytes_exterior (the Scene's exterior faces,
// centroids, projected points and sort buffers).
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo sxmpvo_orderer_info();
}  // namespace vob
