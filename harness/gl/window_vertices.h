// Window positions handed to llvmpipe exactly (the gl sampling rule, raster_rule.h): with a
// power-of-two viewport from the bottom-left corner and w = 1, NDC x = (x - P/2) / (P/2) is
// exact in floats for window coordinates on the 1/256 grid (or any float with few enough
// bits), and so is llvmpipe's viewport transform back: its snapping then sees x itself.
#pragma once
#include <array>

namespace vob::gl {

struct Pow2Viewport {
  int w = 1, h = 1;  // the smallest powers of two >= the framebuffer's size
  explicit Pow2Viewport(int width, int height) {
    while (w < width) w *= 2;
    while (h < height) h *= 2;
  }
  // NDC x, y (w = 1) of window position (x, y); exact when x and y are floats.
  std::array<float, 2> ndc(double x, double y) const {
    const double hx = 0.5 * w, hy = 0.5 * h;
    return {float((x - hx) / hx), float((y - hy) / hy)};
  }
};

}  // namespace vob::gl
