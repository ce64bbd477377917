// Plugins `mpvo` and `mpvonc`: Williams' Meshed Polyhedra Visibility Ordering and its
// nonconvex heuristic (Cook et al., SXMPVO paper, sections 3.2 and 3.3), on MpvoCore.
//
// mpvo      renumber=true curve=hilbert|morton: prepare first renumbers cells and points
//           along a space-filling curve of the cell centroids (phase "renumber along a space
//           curve", MpvoCore), so the DFS walks cells close in memory; orders and cycle
//           reports are in input ids either way. keep_coherent=true (default): only when
//           the curve's numbering has fewer far point reuses than the input's (phase
//           "numbering coherence"; generated meshes are often numbered better already).
//           Phases "I create partial order" (face arrows, sink cells), "II DFS" (from
//           each sink cell in cell-id order, then from cells left unvisited by cycles).
//           Exact on convex, acyclic meshes. Across the gaps of a nonconvex or disconnected
//           mesh it knows no relation, so its error there is what the oracle measures.
// mpvonc    renumber=true curve=hilbert, as mpvo.
//           Phases "I create partial order", "II sort exterior cells" (cells owning a
//           front-facing boundary face, by decreasing centroid depth: distance to the eye,
//           or depth along the view direction for orthographic views; LSD radix sort),
//           "III DFS" (from those cells in that order, then the remaining sinks, then
//           cells left unvisited by cycles). A heuristic on nonconvex meshes.
//
// Both claim nothing (Claims{} = heuristic): a claim holds for every scene and most
// scenes are not convex. Both report and break visibility cycles (detects_cycles).
// Counters: exact_sign_calls, double_sign_wrong, arrows, sink_cells, cycle_roots
// (DFS roots needed after the sinks: cells whose front paths all end in cycles), renumbered
// (0/1), far_reuse_input and far_reuse_curve (when measured), and for mpvonc exterior_cells.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo mpvo_orderer_info();
OrdererInfo mpvonc_orderer_info();
}  // namespace vob
