// Plugin `centroid`: cells sorted back to front by a per-cell key with the LSD radix sort.
// Parameters (key: eye distance or view depth of the centroid) are declared once, in
// centroid_orderer_info(); `vobench list` prints them.
// A heuristic: exact on no class of nonconvex meshes; its error is what the oracle measures.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo centroid_orderer_info();
}
