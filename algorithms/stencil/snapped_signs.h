// Face signs as llvmpipe sees them (the gl sampling rule, harness/raster/raster_rule.h):
// for stencil-xmpvo's GL backend, whose order must hold for the snapped geometry it draws
// and the gl rule judges. A face whose exact projection is a sliver thinner than the
// 1/256-pixel grid can come out of the snapping with the opposite winding: then every
// pixel centre it covers sees the neighbour that the exact test put behind it in front
// (the snapped cells are still convex and meet at the face, only the face is tilted past
// the view direction). MPVO's arrow and the exterior face's facing then follow the snapped
// winding: the sign of the face's fixed-point signed area (quads: of the whole quad, the
// sum of its two halves), window y up, counter-clockwise seen from the side its normal
// points to. A face with a vertex not in front of the eye, or of zero snapped area (it
// covers no pixel), keeps its exact sign.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/mpvo/mpvo_core.h"
#include "harness/view/camera.h"

namespace vob::stencil {

// Applies the snapped signs to `core` (after create_partial_order(view)); returns how many
// faces changed sign. `scratch` keeps the snapped points between frames.
int64_t apply_snapped_signs(mpvo::MpvoCore& core, const Camera& view, std::vector<int64_t>& scratch);

}  // namespace vob::stencil
