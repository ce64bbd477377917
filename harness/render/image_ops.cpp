// Image comparison: what ordering errors do to the picture.
#include <algorithm>
#include <cmath>
#include <string>

#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr double kOff = 1.0 / 255.0;  // one step of an 8-bit channel

void check_same_size(const Image& a, const Image& b, const char* what) {
  if (a.width != b.width || a.height != b.height ||
      a.rgb.size() != size_t(a.width) * a.height * 3 || b.rgb.size() != a.rgb.size())
    throw InputError("image", what,
                     "images differ in size: " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
}
}  // namespace

nlohmann::json ImageError::to_json() const {
  return {{"rmse", rmse}, {"max_error", max_error}, {"pixels_off", pixels_off}};
}

ImageError image_error(const Image& a, const Image& b) {
  check_same_size(a, b, "image_error");
  ImageError e;
  double sum = 0;
  const size_t n = size_t(a.width) * a.height;
  for (size_t p = 0; p < n; ++p) {
    bool off = false;
    for (int c = 0; c < 3; ++c) {
      const double d = std::fabs(double(a.rgb[3 * p + c]) - double(b.rgb[3 * p + c]));
      sum += d * d;
      e.max_error = std::max(e.max_error, d);
      off |= d > kOff;
    }
    e.pixels_off += off;
  }
  e.rmse = n ? std::sqrt(sum / (3.0 * n)) : 0.0;
  return e;
}

Image difference_image(const Image& test, const Image& exact) {
  check_same_size(test, exact, "difference_image");
  Image d = exact;
  const size_t n = size_t(exact.width) * exact.height;
  for (size_t p = 0; p < n; ++p) {
    bool off = false;
    for (int c = 0; c < 3; ++c) off |= std::fabs(test.rgb[3 * p + c] - exact.rgb[3 * p + c]) > kOff;
    for (int c = 0; c < 3; ++c) d.rgb[3 * p + c] = off ? 1.0f : 0.25f * exact.rgb[3 * p + c];
  }
  return d;
}

Image violation_image(const Image& exact, const std::vector<uint8_t>& mask) {
  if (mask.size() != size_t(exact.width) * exact.height)
    throw InputError("image", "violation_image",
                     "mask of " + std::to_string(mask.size()) + " pixels for a " +
                         std::to_string(exact.width) + "x" + std::to_string(exact.height) + " image");
  Image v = exact;
  for (size_t p = 0; p < mask.size(); ++p)
    for (int c = 0; c < 3; ++c)
      v.rgb[3 * p + c] = mask[p] ? (c == 0 ? 1.0f : 0.0f) : kViolationDim * exact.rgb[3 * p + c];
  return v;
}

int64_t marked_pixels(const Image& img) {
  int64_t n = 0;
  const auto byte = [](float v) { return std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f); };
  for (size_t p = 0; p + 2 < img.rgb.size(); p += 3)
    n += byte(img.rgb[p]) == 255 && byte(img.rgb[p + 1]) == 0 && byte(img.rgb[p + 2]) == 0;
  return n;
}

}  // namespace vob
