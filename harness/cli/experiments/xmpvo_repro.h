// Reproductions for XMPVO (Silva, Mitchell, Williams 1998) and BSP-XMPVO (Comba et al.
// 1999) as Cook et al. compare them (IEEE TVCG 10(6), 2004, Table 2): per-view times of
// the object-space orderers beside SXMPVO, preprocessing shown separately. Each writes
// NAME.md / NAME.json (our numbers beside the paper's) and, for the scaling, a figure.
// Orderers not registered in this build are skipped with a note.
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

// cook-table2: BSP-XMPVO, XMPVO and SXMPVO on stand-ins for bluntfin (tet-femur) and f117
// (a 240k-cell gap mesh) at Cook's image sizes.
int xmpvo_cook_table2(const ExperimentContext& ctx);
// xmpvo-scaling: time against b (exterior faces) over the gap series at a fixed size.
int xmpvo_scaling(const ExperimentContext& ctx);

}  // namespace vob
