// Generated (not sorted) back-to-front orders of a VoxelGrid's significant voxels, after
// Botha and Post, "Improved perspective visibility ordering for object-order volume
// rendering" (sections 2 to 4). All four skip empty space with run-length runs of
// significant voxels (grid_traversal.h) and are heuristic under the splat oracle.
//
// Plugin `btf` (Frieder et al.): a traversal direction per axis from the sign of the view
//   direction, fixed nesting z (outer), y, x (inner). No parameters.
// Plugin `wbtf` (Westover): btf's directions, axes nested by |view direction component|:
//   the axis most perpendicular to the view plane outermost. No parameters.
// Plugin `pbtf` (Anderson, Max, Swan): the planes through the eye orthogonal to the axes cut
//   the volume into up to 8 subvolumes (corner-on 1, edge-on 2, face-on 4, volume-on 8), each
//   traversed towards the eye, completely, one after the other. Orthographic views: one
//   subvolume along the view direction.
//   Parameter permute (declared in pbtf_orderer_info()): the nesting of every subvolume;
//   fixed is the paper's Table 1 "unpermuted", wbtf Swan's test implementation.
// Plugin `ip-pbtf` (Botha and Post): pbtf's subvolumes interleaved (voxels at equal distance
//   from a dividing plane alternate, Algorithms 2 and 3) and permuted: the outer axis is one
//   that no dividing plane is orthogonal to (section 4.1), the most perpendicular to the view
//   plane in the volume-on case (section 4.2).
//   Parameter interleave (declared in ip_pbtf_orderer_info()): implicit interleaves the inner loop over
//   the runs with two run pointers (Algorithm 4, empty-space skipping); explicit steps
//   counters through every grid position (significant or not) on all three axes. Both emit
//   the same order; they differ in time.
//
// Counters: visited (grid positions examined), runs (runs entered), subvolumes, split_axes
// (0 corner-on .. 3 volume-on), occupied_split_axes (those with significant voxels on both
// sides of the dividing plane), outer_axis (0 x, 1 y, 2 z).
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo btf_orderer_info();
OrdererInfo wbtf_orderer_info();
OrdererInfo pbtf_orderer_info();
OrdererInfo ip_pbtf_orderer_info();
}  // namespace vob
