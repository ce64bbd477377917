// Reproductions of Botha and Post (IP-PBTF): `vobench reproduce botha-table1 |
// botha-interleaving | botha-fig1 | botha-violations`. Each writes NAME.md / NAME.json beside
// the paper's numbers (paper machine: 2.4 GHz Pentium 4 with a GeForce4) and its figures
// (reports/botha_figures.py, images through write_png).
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

int botha_table1(const ExperimentContext& ctx);        // ordering throughput by volume
int botha_interleaving(const ExperimentContext& ctx);  // explicit against implicit
int botha_fig1(const ExperimentContext& ctx);          // images, differences, oracle counts
int botha_violations(const ExperimentContext& ctx);    // 14 close-up views per volume

}  // namespace vob
