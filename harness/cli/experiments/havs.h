// Reproductions of Callahan et al. (HAVS): `vobench reproduce havs-table1 | havs-table2 |
// havs-table3-4 | havs-k-tradeoff | havs-gl`. Each writes NAME.md / NAME.json beside the paper's
// numbers (paper machine: 3.2 GHz Pentium 4, 2 GB, ATI Radeon 9800 Pro) and its figures
// (reports/havs_figures.py).
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

int run_havs_table1(const ExperimentContext& ctx);
int run_havs_table2(const ExperimentContext& ctx);
int run_havs_table34(const ExperimentContext& ctx);
int run_havs_k_tradeoff(const ExperimentContext& ctx);
// The k-buffer as an OpenGL fragment shader on OSMesa against the software k-buffer: frame
// times, image differences, and the pixels the read-modify-write race (Fig. 5) changed.
int run_havs_gl(const ExperimentContext& ctx);

}  // namespace vob
