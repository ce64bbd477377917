// Plugin `distance-sort` (voxels): the significant voxels sorted back to front by the
// distance from the eye to the voxel centre (orthographic: depth along the view direction)
// with a 64-bit radix sort, so no tie is lost to float rounding. The correct but costly
// reference Botha and Post name; exact in the splat oracle's sense (depth = eye distance).
// No parameters.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo distance_sort_orderer_info();
}
