// Cook et al. Table 6 counts "tiny" cells: cells that project onto no pixel, which SXMPVO
// (an image-space order) leaves unconstrained. A cell counts as tiny when every ray segment
// it has at a pixel centre is shorter than the oracle's floor, i.e. when the oracle would
// never see it: the same clipper and floor as the oracle (cell_clip.h).
#include "algorithms/sxmpvo/tiny_cells_probe.h"

#include "harness/bench/suite.h"
#include "harness/raster/cell_clip.h"
#include "harness/scene/input_error.h"
#include "harness/view/fit.h"

namespace vob {
namespace {

int64_t tiny_cells(const Scene& s, const Camera& cam) {
  const SampleFrame frame(cam, 1);
  const ProjectedPoints proj = project_points(frame, s.mesh().points);
  CellClipper clip(frame, s.mesh(), proj, oracle_min_segment(s.bounds(), cam));
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
  // side x side pixels: a square image with the suite's first view (the view set's cameras
  // depend on the size only through width and height), or with `fit` that view's window
  // fitted to the bounding box at about side^2 pixels, as Cook et al.'s Table 6 sets it.
  const int side = params.get_int("side", 412, 1, kMaxImageSide);
  const bool fit = params.get_bool("fit", false);
  if (params.dry_run()) return nlohmann::json::object();  // suite validation: parameters only
  if (ctx.scene->kind() != SceneKind::Cells)
    throw InputError(ctx.dataset_label, "sxmpvo-tiny-cells", "needs a cell dataset");
  if (ctx.views.empty()) throw InputError(ctx.dataset_label, "sxmpvo-tiny-cells", "the suite gives no view");
  const auto& [view_index, view] = ctx.views.front();
  Camera cam = view;
  cam.width = cam.height = side;
  if (fit) cam = fit_window_to_box(cam, ctx.scene->bounds(), int64_t(side) * side);
  const int64_t tiny = tiny_cells(*ctx.scene, cam);
  if (ctx.progress)
    ctx.progress("  " + ctx.dataset_label + " at " + std::to_string(cam.width) + "x" +
                 std::to_string(cam.height) + ": " + std::to_string(tiny) + " tiny cells");
  return {{"side", side},
          {"fit", fit},
          {"w", cam.width},
          {"h", cam.height},
          {"pixels", int64_t(cam.width) * cam.height},
          {"view_index", view_index},
          {"cells", ctx.scene->mesh().num_cells()},
          {"tiny_cells", tiny}};
}

}  // namespace

ProbeInfo sxmpvo_tiny_cells_probe_info() {
  return {"sxmpvo-tiny-cells",
          "cells with no ray segment at any pixel centre (Cook et al. Table 6), the first view at side x side (fit: fitted to the bounding box at side^2 pixels)",
          true, run};
}

}  // namespace vob
