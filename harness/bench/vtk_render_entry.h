// A suite's "vtk_render" entry (docs/pipeline.md "Suite"): the orderers vobench-vtk draws in
// VTK's projected-tetrahedra mapper beside VTK's own sort, on the suite's cell datasets,
// views and sizes. Read with the suite (vobench run / reproduce start vobench-vtk for it,
// harness/cli/vtk_render_child.h; vobench-vtk render --suite reads it too).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vob {

class SuiteReader;

struct VtkRenderEntry {
  std::vector<std::string> algorithms;  // cell orderer specs, at least one
  int repeats = 3;
  double extinction = 1.0;
};

// {"algorithms": [...], "repeats": N, "extinction": F, "comment": ...}; InputError naming the
// suite and "vtk_render.KEY" for anything else, an unknown orderer or one of other scenes.
VtkRenderEntry read_vtk_render_entry(const SuiteReader& r, const nlohmann::json& e);

}  // namespace vob
