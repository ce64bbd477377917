// Probes of the voxel orderers (Botha and Post reproductions; docs/pipeline.md, Probes).
//
// Probe `voxel-splat-frames`: whole software splatting frames, the ordering then
// render_in_order (harness/render/compositor.h, every significant voxel splatted at the
//   oracle's default footprint), timed together, on the first `frame_views` of the suite's
//   views. The orderings alternate within each repeat of each view so that load from other
//   processes drifts over all of them alike; one warm-up frame per ordering on the first view.
//   Orderings: btf, pbtf, ip-pbtf (the paper's Table 1). Parameter: frame_views=2 (1..1000).
//   Result: {orderings, views: [view index], seconds: {spec: [[seconds per repeat] per view]}}.
//
// Probe `voxel-order-splits`: per view of the suite, the facts that explain where pbtf's and
//   ip-pbtf's orders differ from btf's and wbtf's: the split axes of pbtf's dividing planes
//   (voxel::eye_splits: kv, eye in index units, occupied slabs of significant voxels below
//   and above the plane) and the positions where the orders differ. No parameters.
//   Result: {views: [{view, cuts: [{axis, kv, e, slabs_below, slabs_above}], pbtf_moved,
//   ip_moved}]} (pbtf_moved: positions where pbtf's order differs from btf's; ip_moved:
//   ip-pbtf's from wbtf's).
#pragma once
#include "harness/bench/probe.h"

namespace vob {
ProbeInfo voxel_splat_frames_probe_info();
ProbeInfo voxel_order_splits_probe_info();
}  // namespace vob
