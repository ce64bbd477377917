// compare_8bit (gl_kbuffer.h): the GL image against the software k-buffer's.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "algorithms/havs/gl/gl_kbuffer.h"

namespace vob::havs {

ImageCompare8 compare_8bit(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compare_8bit: images of different sizes");
  ImageCompare8 c;
  c.pixels = int64_t(a.width) * a.height;
  c.mask.assign(c.pixels, 0);
  const auto q = [](float v) { return int(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); };
  double sum = 0;
  for (int64_t p = 0; p < c.pixels; ++p) {
    int worst = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int dd = std::abs(q(a.rgb[3 * p + ch]) - q(b.rgb[3 * p + ch]));
      sum += double(dd) * dd;
      worst = std::max(worst, dd);
    }
    c.max_diff = std::max(c.max_diff, worst);
    c.mask[p] = worst != 0;
    c.differing += worst != 0;
    c.differing_by_more_than_1 += worst > 1;
  }
  c.rms = c.pixels ? std::sqrt(sum / (3.0 * c.pixels)) : 0;
  return c;
}

}  // namespace vob::havs
