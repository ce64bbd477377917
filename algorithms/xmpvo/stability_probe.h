// Probe `xmpvo-stability`: XMPVO's sign decisions in plain doubles against the exact
// predicates on one scene, over the suite's views of it (docs/pipeline.md "Probes").
//
// Per view it orders the scene with xmpvo:predicates=compare (decides with the exact signs,
// identical to the default, and counts where doubles would have decided otherwise) and with
// xmpvo:predicates=double, and judges both orders with the oracle. The result sums over the
// views: decisions and disagreements (arrows, facing, crossings, sides), failing views,
// violating pixels and cycles of both orders, face pairs left undecided; "per_view" keeps
// each view's numbers. No parameters.
#pragma once
#include "harness/bench/probe.h"

namespace vob {
ProbeInfo xmpvo_stability_probe_info();
}  // namespace vob
