// A window fitted to the data (Cook et al. 2004, Tables 1, 2 and 5: "the window size was set
// to match the bounding box of the data set"): the camera keeps its eye, target and up; its
// window takes the aspect ratio of the bounding box's projection at about `pixels` pixels,
// and its field of view (or orthographic height) frames that projection, touching it on the
// tighter side. The frustum stays symmetric about the view direction, which passes through
// the box centre, so the box is centred and nearly fills the window.
#pragma once
#include <cstdint>

#include "harness/view/camera.h"

namespace vob {

// InputError when a corner of the box is not in front of the eye (perspective) or
// `pixels` is below 1 or above 16384^2.
Camera fit_window_to_box(const Camera& c, const Aabb& box, int64_t pixels);

}  // namespace vob
