// The C++ experiments not yet converted to reproduction files (docs/pipeline.md); `vobench
// reproduce` falls back to this list for names no reproduction file has.
#include "harness/cli/experiments.h"
#include "harness/cli/experiments/botha.h"
#include "harness/cli/experiments/cook.h"
#include "harness/cli/experiments/havs.h"
#include "harness/cli/experiments/krishnan.h"

namespace vob {

const std::vector<Experiment>& experiment_registry() {
  static const std::vector<Experiment> registry = {
      {"havs-table1", "HAVS Table 1: shellsort, heapsort, quicksort, stable sort and radix sort of 1M floats; VTK's sorter on 1M cells", run_havs_table1},
      {"havs-table2", "HAVS Table 2: fragments, max A-buffer list, max k, pixels needing k > 2 and > 6 over 14 views at 512x512, Fig. 6 maps", run_havs_table2},
      {"havs-table3-4", "HAVS Tables 3 and 4: cpu sort and k-buffer time per frame and cells/s for k = 2 and 6", run_havs_table34},
      {"havs-k-tradeoff", "HAVS: time against error as k grows (1..8), beside the cell orderers", run_havs_k_tradeoff},
      {"havs-gl", "HAVS: the k-buffer as an OpenGL fragment shader on OSMesa against the software k-buffer: times, image differences, race-changed pixels (Fig. 5)", run_havs_gl},
      {"botha-table1", "Botha and Post Table 1: ordering throughput of btf, wbtf, pbtf, ip-pbtf, distance-sort on 256^3-class volumes at 512x512", botha_table1},
      {"botha-interleaving", "Botha and Post: explicit against implicit interleaving (empty-space skipping) on sparse and dense volumes", botha_interleaving},
      {"botha-fig1", "Botha and Post Fig. 1: a close-up in btf, pbtf and ip-pbtf order, difference images against distance-sort, oracle counts", botha_fig1},
      {"botha-violations", "Botha and Post: violating pixels of every voxel ordering over 14 close-up views per volume", botha_violations},
      {"cook-table1", "Cook et al. Table 1: n, n/log2 n, b, a, w*h for gap, helix, zoo and TetGen meshes", cook_table1},
      {"cook-table3", "Cook et al. Table 3: SXMPVO's four phases by mesh size, PN and A-buffer counts, memory", cook_table3},
      {"cook-table4", "Cook et al. Table 4: SXMPVO against MPVONC and vtk-centroid by mesh size at 512x512", cook_table4},
      {"cook-table2-5", "Cook et al. Tables 2 and 5: SXMPVO time against image size (170k to 2M pixels)", cook_table2_5},
      {"cook-fig8", "Cook et al. Fig. 8: helix rendered in MPVONC and SXMPVO order, difference, oracle counts", cook_fig8},
      {"cook-fig11", "Cook et al. Fig. 11: SXMPVO time against exterior-face area over 0..95 gaps", cook_fig11},
      {"cook-table6", "Cook et al. Table 6: tiny cells (no pixel centre) against image size", cook_table6},
      {"krishnan-table1", "Krishnan et al. Table 1: vertices, triangles, layers and depth complexity at 256^2 and 512^2 over a 30-frame orbit", krishnan_table1},
      {"krishnan-fig2", "Krishnan et al. Fig. 2: render/read/scan shares, naive against blocked layer extraction, speedup per model", krishnan_fig2},
      {"krishnan-fig3", "Krishnan et al. Fig. 3: triangles coloured by layer and each layer's footprint (PNGs)", krishnan_fig3},
      {"krishnan-xmpvo", "Krishnan et al. section 4: stencil-xmpvo time and oracle error beside sxmpvo (and xmpvo, bsp-xmpvo)", krishnan_xmpvo},
  };
  return registry;
}

}  // namespace vob
