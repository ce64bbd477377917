// Plugin `xmpvo`: Silva, Mitchell and Williams' XMPVO (VolVis 1998), as specified in issue 4:
// MPVO's face arrows plus relations between exterior cells found at object precision.
//
// Parameter predicates (declared in xmpvo_orderer_info()):
//   predicates  exact: every sign (front/back facing, side of a projected edge,
//               edge crossing, arrow) is an exact predicate (CGAL filtered);
//               double: the same signs in plain double arithmetic, no filter, no fallback
//               (face depth order stays exact) -- for the stability study only;
//               compare: evaluate both, use the exact sign, count disagreements
//               (counters disagree_facing, disagree_side, disagree_crossing, and
//               disagree_arrows = MpvoCore's double_sign_wrong).
//
// Prepare: "unique faces", "face planes", "exterior faces" (the Scene's), "exterior face
// planes".
// Phases per view:
//   "I create partial order"  MPVO face arrows (MpvoCore);
//   "project"  exterior faces with their facing (edge-on faces dropped: they cover no open
//       set; perspective faces not entirely in front of the eye skipped and counted),
//       vertices projected to doubles for bucketing only, a uniform grid of about one face
//       per bucket;
//   "arrangement vertices"  projected face vertices plus proper crossings of projected
//       edges, found among edge pairs sharing a bucket (exact crossing test);
//   "ray queries"  at each arrangement vertex v: the faces whose closed projection holds v
//       (exact sides), split into those with v inside (sorted by exact depth order) and
//       those with v on their boundary (a wedge of directions). Each sector between
//       consecutive boundary directions is a region touching v; its faces are the inside
//       ones plus the boundary ones covering it, in depth order -- the ray shot just inside
//       the region, symbolically. Two faces covering a region at v are ordered by where
//       v's own ray meets their planes (exact, vertex_plane_order), and by the full
//       depth_order only when they touch on that ray. Points get such a full query; each
//       projected edge with crossings a sweep along it that keeps the covering faces sorted
//       and emits the pairs next to its own faces on each segment (edge_sweep.cpp;
//       crossings get no query of their own), with full queries wherever its premises
//       fail. On a conforming surface in exact mode the front sheet's inner edges (two
//       front faces on either side) are not swept, and the arrangement leaves out their
//       crossings with each other: the same relations (edge_sweep.cpp); a view that needs
//       full queries at every vertex builds the arrangement again, in this phase.
//       Queries run in parallel (TBB); the relation set does not depend on the
//       thread split.
//       Consecutive (back-facing nearer, front-facing farther)
//       pairs give "cell of the nearer in front of cell of the farther". Only pairs next to
//       a boundary face are taken (and the inside faces' pair a boundary face separates in
//       a sector it does not cover, when no covering boundary face lies between them): a
//       run of regions where a pair stays consecutive is bounded by edges of the pair or of
//       faces between them, so one of its corners has such a face. Every relation is
//       between faces consecutive on some ray, which is all the order needs.
//   "DFS"  MpvoCore's DFS with the relations (sinks, then unvisited cells; cycles reported
//       and broken).
//
// Exact mode filters in doubles first (uv_filter.h: sides and crossings from the projected
// doubles with a bound for every rounding; plane_keys.h: each face's depth key once per
// query, with a running error bound) and calls the exact predicates only where the double
// answer is too close to call; double and compare modes run no filter.
//
// Limits: faces crossing a perspective eye's plane (eye inside or beside the mesh) are
// skipped (counter faces_crossing_eye_plane); rays near them may miss relations. Faces
// are taken as planar convex polygons (the plane of the first three vertices).
//
// Claims: object_exact (every ray, any resolution, acyclic valid meshes), detects_cycles.
// Counters: MpvoCore's, exterior_faces, front_facing, back_facing, edge_on_faces,
// faces_behind_eye, faces_crossing_eye_plane, skipped_faces, projected_vertices,
// edge_crossings, candidate_edge_pairs, vertex_queries, ray_queries (sectors),
// faces_per_query (mean faces in a sector's list), relations (distinct extra pairs),
// depth_order_calls, depth_order_full (those needing the full test), depth_undecided
// (intersecting faces, or coplanar ones facing the same way; coplanar faces facing
// opposite ways -- volumes touching face to face -- are ordered by coplanar_order), degenerate_coverage (a face whose projection is met
// in a degenerate way at a vertex, skipped), grid_buckets, bytes_*; in compare mode the
// disagree_* counts and decision totals facing_decisions, side_decisions,
// crossing_decisions. The filters' share: side_filtered / side_rechecked (side tests the
// double filter decided / left to the exact predicate), crossings_filtered /
// crossings_rechecked (candidate edge pairs), depth_rechecked (depth keys, or the sweep's
// plane sides, too close to call), queries_rechecked (vertex queries or swept edges with any exact re-check);
// sweep_edges, sweep_crossings (crossings the sweeps passed, two per crossing),
// sweep_fallbacks (edges whose crossings got full queries), depth_plane_sides (sweep depth
// comparisons decided by the sides of a face plane alone), sweep_swaps (crossings whose
// entering face took the leaving face's place), touched_exterior_edges (exterior edges an
// exterior face not having them meets, found in prepare; -1 with quadrilaterals: on 0 the
// swaps compare no depths), depth_edge_orders
// (sweep depth comparisons of a face of the swept edge with an entering face, decided by the
// orientation of the two edges), sweep_end_queries (point queries that took their faces
// from a sweep ending there), sheet_edges_unswept (inner edges of the front sheet left
// out), arrangement_rebuilt (1: the view needed every crossing); vertex_queries
// counts every vertex ray a query or the sweep built. edge_crossings and
// candidate_edge_pairs leave out the pairs of two unswept edges.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo xmpvo_orderer_info();
}  // namespace vob
