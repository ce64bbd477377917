// Reproductions of Cook, Max, Silva and Williams, "Image-Space Visibility Ordering for
// Cell Projection Volume Rendering of Unstructured Data" (IEEE TVCG 10(6), 2004): SXMPVO.
// Each writes NAME.md / NAME.json (our numbers beside the paper's) and its figures to
// ctx.out_dir; ctx.full runs the paper's full sizes where the default is smaller.
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

int cook_table1(const ExperimentContext& ctx);    // n, n/log2 n, b, a, w*h
int cook_table3(const ExperimentContext& ctx);    // four-phase breakdown, memory per structure
int cook_table4(const ExperimentContext& ctx);    // SXMPVO vs MPVONC (and VTK) by mesh size
int cook_table2_5(const ExperimentContext& ctx);  // time against image size
int cook_fig8(const ExperimentContext& ctx);      // helix: MPVONC vs SXMPVO images, oracle
int cook_fig11(const ExperimentContext& ctx);     // time against exterior-face area (gaps)
int cook_table6(const ExperimentContext& ctx);    // tiny cells against image size

}  // namespace vob
