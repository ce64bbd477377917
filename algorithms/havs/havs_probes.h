// Probes of the HAVS plugin that are not orderer frames (docs/pipeline.md, "Probes"):
// - havs-sorts: Table 1's sorts of n (float, id) pairs (reference_sorts.h and the harness
//   radix sort), timed one sort per record.
// - havs-analysis: Table 2's per-view k-buffer analysis of a mesh and the Fig. 6 map of the
//   view needing the largest k most often.
#pragma once
#include "harness/bench/probe.h"

namespace vob {

ProbeInfo havs_sorts_probe_info();
ProbeInfo havs_analysis_probe_info();

}  // namespace vob
