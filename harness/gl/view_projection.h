// The view-projection matrix of a Camera for OpenGL, the one used by every GL plugin. It
// uses Camera::half_extents like SampleFrame, so that a vertex lands at the window
// coordinates SampleFrame::project gives it (tests/harness/gl/view_projection_test.cpp).
#pragma once
#include <array>

#include "harness/geometry/vec3.h"
#include "harness/view/camera.h"

namespace vob::gl {

struct ProjectionOptions {
  Vec3 origin{};        // vertices are given as world position - origin
  bool depth = false;   // false: clip z = 0, so nothing is clipped by a near or far plane
  double near = 0;      // with depth: view depths (along forward from the eye) mapped
  double far = 1;       //   to NDC z = -1 and +1
  bool flip_y = false;  // draw upside down: GL window row H-1-j is our row j
};

// Column-major 4x4 matrix in doubles: clip x = (p - eye).right / half_x and clip y =
// (p - eye).up / half_y, clip w = (p - eye).forward (perspective) or 1 (orthographic).
std::array<double, 16> view_projection(const Camera& view, const ProjectionOptions& opt = {});

}  // namespace vob::gl
