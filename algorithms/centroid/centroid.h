// Plugin `centroid`: cells sorted back to front by a per-cell key with the LSD radix sort.
//   key=eye  (default) distance from the eye to the cell centroid
//   key=view depth of the centroid along the view direction (the key VTK's
//            vtkCellCenterDepthSort uses)
// A heuristic: exact on no class of nonconvex meshes; its error is what the oracle measures.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo centroid_orderer_info();
}
