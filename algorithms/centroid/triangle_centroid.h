// Plugin `triangle-centroid` (triangles): triangles sorted back to front by the eye
// distance of their centroids with the float LSD radix sort. The painter's heuristic for
// surface scenes: wrong wherever triangles overlap in depth; the oracle measures by how much.
// No parameters.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo triangle_centroid_orderer_info();
}
