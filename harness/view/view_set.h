// Deterministic view sets around a bounding box: N eyes on a Fibonacci sphere at
// kViewDistance bounding radii from the centre, or an orbit of F frames.
#pragma once
#include <vector>

#include "harness/view/camera.h"

namespace vob {

constexpr double kViewDistance = 3.0;  // in bounding radii; with 40 deg fov the box fits
constexpr double kViewFov = 40.0;

struct ViewOptions {
  int width = 512, height = 512;
  bool ortho = false;     // orthographic views framing the bounding sphere
  double zoom = 1.0;      // > 1 moves the eye closer (close-up views)
};

// View i of a set of n on the Fibonacci sphere (i in [0, n)).
Camera fibonacci_view(const Aabb& box, int n, int i, const ViewOptions& opt = {});
std::vector<Camera> fibonacci_views(const Aabb& box, int n, const ViewOptions& opt = {});
// Frame f of an F-frame orbit around the box (tilted 30 degrees above the equator).
Camera orbit_view(const Aabb& box, int frames, int f, const ViewOptions& opt = {});

}  // namespace vob
