// Cook et al. Table 6 counts "tiny" cells: cells that project onto no pixel, which SXMPVO
// (an image-space order) leaves unconstrained. A cell counts as tiny when every ray segment
// it has at a pixel centre is shorter than the oracle's floor, i.e. when the oracle would
// never see it: the same clipper and floor as the oracle (cell_clip.h).
#include "algorithms/sxmpvo/tiny_cells_probe.h"

#include "harness/bench/suite.h"
#include "harness/raster/cell_clip.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

int64_t tiny_cells(const Scene& s, const Camera& cam) {
  const SampleFrame frame(cam, 1);
  const ProjectedPoints proj = project_points(frame, s.mesh().points);
  CellClipper clip(frame, s.mesh(), proj, kMinSegmentRelative * s.bounds().radius());
  int64_t tiny = 0;
  for (int32_t c = 0; c < static_cast<int32_t>(s.mesh().num_cells()); ++c) {
    const SampleRect r = clip.bounds(c).intersect(frame.bounds());
    bool hit = false;
    if (!r.empty()) {
      clip.setup(c);
      clip.scan(r, [&](int, int, double, double) { hit = true; });
    }
    tiny += !hit;
  }
  return tiny;
}

nlohmann::json run(Params& params, const ProbeContext& ctx) {
  // Square images side x side; the camera is the suite's first view with that size (the
  // view set's cameras depend on the size only through width and height).
  const int side = params.get_int("side", 412, 1, kMaxImageSide);
  if (params.dry_run()) return nlohmann::json::object();  // suite validation: parameters only
  if (ctx.scene->kind() != SceneKind::Cells)
    throw InputError(ctx.dataset_label, "sxmpvo-tiny-cells", "needs a cell dataset");
  if (ctx.views.empty()) throw InputError(ctx.dataset_label, "sxmpvo-tiny-cells", "the suite gives no view");
  const auto& [view_index, view] = ctx.views.front();
  Camera cam = view;
  cam.width = cam.height = side;
  const int64_t tiny = tiny_cells(*ctx.scene, cam);
  if (ctx.progress)
    ctx.progress("  " + ctx.dataset_label + " at " + std::to_string(side) + "x" + std::to_string(side) +
                 ": " + std::to_string(tiny) + " tiny cells");
  return {{"side", side},
          {"pixels", int64_t(side) * side},
          {"view_index", view_index},
          {"cells", ctx.scene->mesh().num_cells()},
          {"tiny_cells", tiny}};
}

}  // namespace

ProbeInfo sxmpvo_tiny_cells_probe_info() {
  return {"sxmpvo-tiny-cells",
          "cells with no ray segment at any pixel centre (Cook et al. Table 6), view 0 at side x side",
          true, run};
}

}  // namespace vob
