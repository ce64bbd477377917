// Reproductions of Krishnan, Silva and Wei, "A Hardware-Assisted Visibility-Ordering
// Algorithm With Applications To Volume Rendering" (2001): `vobench reproduce
// krishnan-table1 | krishnan-fig2 | krishnan-fig3 | krishnan-xmpvo`. Paper machines: SGI
// Octane (300 MHz R12000, EMXI graphics) and HP PC (2 x 450 MHz Pentium II Xeon, HP fx6);
// ours: OSMesa llvmpipe on this machine's CPU. Each writes NAME.md / NAME.json (and PNGs
// for fig3) to ctx.out_dir; ctx.full adds the 52k-triangle armadillo and more frames.
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

int krishnan_table1(const ExperimentContext& ctx);  // vertices, triangles, depth at 256^2, 512^2
int krishnan_fig2(const ExperimentContext& ctx);    // read and scan shares, naive vs blocked
int krishnan_fig3(const ExperimentContext& ctx);    // triangles coloured by layer, footprints
int krishnan_xmpvo(const ExperimentContext& ctx);   // stencil-xmpvo against sxmpvo (and xmpvo)

}  // namespace vob
