#include "vtk/render/image_compare.h"

#include <cstdlib>
#include <stdexcept>

#include "harness/render/compositor.h"

namespace vob {

int64_t covered_pixels(const RgbImage& a) {
  int64_t n = 0;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) n += (a.rgb[i] | a.rgb[i + 1] | a.rgb[i + 2]) != 0;
  return n;
}

PixelDiff compare_images(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::logic_error("compare_images: sizes differ");
  PixelDiff d;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    int m = 0;
    for (size_t k = i; k < i + 3; ++k) m = std::max(m, std::abs(int(a.rgb[k]) - int(b.rgb[k])));
    if (m > 0) ++d.pixels;
    d.max = std::max(d.max, m);
  }
  return d;
}

namespace {
Image to_float(const RgbImage& a, float scale) {
  Image img;
  img.width = a.width;
  img.height = a.height;
  img.rgb.resize(a.rgb.size());
  for (size_t i = 0; i < a.rgb.size(); ++i) img.rgb[i] = scale * a.rgb[i] / 255.0f;
  return img;
}
}  // namespace

void write_rgb_png(const RgbImage& a, const std::string& path) { write_png(to_float(a, 1.0f), path); }

void write_difference_png(const RgbImage& a, const RgbImage& ref, const std::string& path) {
  Image img = to_float(ref, 0.3f);
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3)
    if (a.rgb[i] != ref.rgb[i] || a.rgb[i + 1] != ref.rgb[i + 1] || a.rgb[i + 2] != ref.rgb[i + 2])
      img.rgb[i] = img.rgb[i + 1] = img.rgb[i + 2] = 1.0f;
  write_png(img, path);
}

}  // namespace vob
