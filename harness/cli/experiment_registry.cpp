// The list of reproducible experiments. Add one: write a function in experiments/ and a
// line here.
#include "harness/cli/experiments.h"

namespace vob {

const std::vector<Experiment>& experiment_registry() {
  static const std::vector<Experiment> registry = {
      {"quick",
       "the default job: small gap, helix and zoo meshes, a TetGen mesh, a surface and a "
       "volume, every registered orderer, with a report",
       [](const ExperimentContext& ctx) {
         return run_suite_experiment({"quick.json", "quick-helix.json"}, "quick", "vobench quick report", ctx);
       }},
      {"peer-1m",
       "centroid:key=view against VTK's vtkCellCenterDepthSort (and MPVO, MPVONC) on a "
       "1M-cell gap mesh, 3 views",
       [](const ExperimentContext& ctx) {
         return run_suite_experiment({"peer-1m.json"}, "peer-1m", "the peer sorter on 1M cells", ctx);
       }},
  };
  return registry;
}

}  // namespace vob
