// Plugin `bsp-xmpvo`: Comba, Klosowski, Max, Mitchell, Silva and Williams' BSP-XMPVO
// (Computer Graphics Forum 18(3), 1999), on MpvoCore: MPVO's face arrows plus relations
// between exterior cells found at object precision through a view-independent BSP tree of
// the exterior faces (bsp_tree.h).
//
// Parameters candidates, sample, split_weight, stop: declared in bsp_xmpvo_orderer_info();
//   stop        end a beam's front-to-back traversal once its cross-section is proved covered
//               (false: collect every candidate in the beam; same order, more relations).
//
// Prepare: "unique faces", "face planes", "exterior faces" (the Scene's), "BSP build"
// (exterior triangles split exactly by face planes and, where those do not divide, by
// axis-aligned median planes, bsp_tree.h; depth, nodes, fragments and bytes in the
// counters). Prepare is timed apart from the per-view phases below (records: `prepare`).
// Phases per view:
//   "create partial order"  MPVO phase I: face arrows and outbound counts;
//   "tree work"  for every back-facing exterior triangle X (the ray leaves the mesh there),
//       a front-to-back traversal of the tree restricted to X's shadow beam
//       {eye + s (x - eye): x in X, s >= 1} ({x + s dir: s >= 0} for orthographic views). At
//       a node the beam is tested exactly against the node's plane (X's vertices by orient3d,
//       the recession directions by an exact sign of det); a beam on one closed side visits
//       that side only, otherwise near side, the node's coplanar items (through their box
//       hierarchy, culled by the box's axis planes, X's plane and X's edge planes, exactly;
//       whole subtrees are culled the same way by the box of their triangles),
//       then far side; when X lies in the node's plane, the node's coplanar items and then
//       the far side (a volume touching X's face to face starts there). Candidates are
//       front-facing exterior triangles of another cell not separated from the beam by X's
//       plane (triangles in X's plane are not) or one of X's edge planes (exact). With stop,
//       when a node's plane cuts every ray of the beam and its front-facing items cover that
//       cross-section (proved without constructions: no boundary edge of their union meets
//       the open cone of X, and one of them overlaps X), every ray has entered the mesh by
//       then, so the traversal ends (`early_stops`); BSP order puts everything later behind;
//   "glue"  per candidate pair (X, Y): exact projections_overlap and depth_order
//       (face_pairs.h; coplanar X and Y are ordered by coplanar_order, X first); X in front
//       gives the relation cell(X) in front of cell(Y). Every such
//       relation holds along a real ray (cells do not overlap), so this superset of the pairs
//       consecutive along rays is consistent; deduplicated, it becomes MpvoCore's extra
//       relations, and cells behind lose their sink flag;
//   "DFS"  from every sink, then cells left unvisited by cycles (reported, broken).
// Perspective views: a triangle not entirely in front of the plane through the eye normal
// to the view direction (eye inside the mesh, eye in a face plane) is skipped in the
// search and counted in `skipped_triangles`; the order stays complete but is exact only
// when that count is 0.
//
// Claims: object_exact (exact for every ray when skipped_triangles = 0 and the mesh is
// acyclic), detects_cycles.
// Counters: MpvoCore's, exterior_triangles, bsp_nodes, bsp_depth, bsp_fragments,
// bsp_splits, fragment_growth, bsp_build_seconds, bsp_free_nodes, bsp_filtered_tests,
// bsp_exact_tests, bsp_point_tests (bsp_tree.h's BspStats), bytes_bsp, per view back_facing,
// front_facing, skipped_triangles, beam_queries, nodes_visited, boxes_visited,
// candidates, overlap_tests, depth_undecided, early_stops, relations (distinct cell pairs), bytes_mpvo,
// bytes_relations.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo bsp_xmpvo_orderer_info();
}  // namespace vob
