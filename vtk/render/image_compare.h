// The rendered images of `vobench-vtk render`, compared byte by byte: a pixel differs when
// any of its 8-bit channels does (the framebuffer's own precision, no tolerance).
#pragma once
#include <cstdint>
#include <string>

#include "vtk/render/vtk_frame.h"

namespace vob {

struct PixelDiff {
  int64_t pixels = 0;  // pixels with some channel different
  int max = 0;         // largest channel difference, 0..255
};

int64_t covered_pixels(const RgbImage& image);  // pixels other than black
PixelDiff compare_images(const RgbImage& image, const RgbImage& reference);
// PNGs through vobench's writer (row 0 at the bottom, as read back from GL).
void write_rgb_png(const RgbImage& image, const std::string& path);
// White where `image` differs from `reference`, the reference dimmed to 30% elsewhere.
void write_difference_png(const RgbImage& image, const RgbImage& reference, const std::string& path);

}  // namespace vob
