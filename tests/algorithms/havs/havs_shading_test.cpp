// HAVS shading: the k-buffer's float opacity (one expf per segment) against the double
// reference that the analysis' exact image uses, within the bound kbuffer.h states; and a
// whole frame rendered both ways differs per pixel by at most that bound per segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "algorithms/havs/havs_frame.h"
#include "tests/algorithms/havs/havs_views.h"
#include "tests/support/test_util.h"

namespace vob {
namespace {

constexpr double kAlphaBound = 4e-7;  // as stated in kbuffer.h

std::string sci(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

// One segment composited into an empty, inside pixel: its colour weight is its opacity.
float opacity(const havs::Shading& sh, float d1, float d2, float v1, float v2) {
  havs::PixelAccum px;
  px.inside = true;
  sh.segment(px, havs::KEntry{d1, v1, 0}, havs::KEntry{d2, v2, 0});
  return px.a;
}

TEST(HavsShading, FloatOpacityWithinBoundOfDouble) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (double tau0 : {0.05, 0.4, 2.4, 12.0}) {
    const havs::Shading fast{tau0}, ref{tau0, true};
    for (int i = 0; i < 200000; ++i) {
      const float d1 = float(0.5 + 40 * u(rng));
      // Segment lengths from 1e-7 to ~10 mesh radii: opacities from ~0 to 1.
      const float d2 = d1 + float(std::pow(10.0, -7 + 8 * u(rng)) / tau0);
      const float v1 = float(u(rng)), v2 = float(u(rng));
      worst = std::max(worst, double(std::fabs(opacity(fast, d1, d2, v1, v2) - opacity(ref, d1, d2, v1, v2))));
    }
  }
  RecordProperty("max_opacity_difference", sci(worst));
  EXPECT_LE(worst, kAlphaBound);
  EXPECT_GT(worst, 0);  // the two paths do differ: the comparison is not of one function
}

TEST(HavsShading, FrameImageWithinBoundPerSegment) {
  const Scene scene = test::small_mesh("helix");
  const havs::FaceData fd = havs::build_face_data(scene);
  const Camera cam = test::havs_view(scene, 3, 96);
  const std::vector<int32_t> order = test::havs_face_order(fd, cam);
  // The analysis' exact image uses the double shading; with k >= max k needed the k-buffer
  // composites the same segments, so the images differ only by the shading.
  const int need = havs::analyze(fd, cam, order, 1).max_k_needed;
  ASSERT_LE(need, havs::kMaxK);
  havs::AnalysisOptions opt;
  opt.record_segments = true;
  const havs::Analysis a = havs::analyze(fd, cam, order, need, opt);
  ASSERT_EQ(a.violating_pixels, 0);
  double worst = 0;
  for (int64_t p = 0; p + 1 < int64_t(a.seg_offsets.size()); ++p) {
    const double segs = double(a.seg_offsets[p + 1] - a.seg_offsets[p]);
    for (int c = 0; c < 3; ++c) {
      const double diff = std::fabs(a.kbuffer_image.rgb[3 * p + c] - a.exact_image.rgb[3 * p + c]);
      EXPECT_LE(diff, 2 * kAlphaBound * std::max(1.0, segs) + 1e-6) << "pixel " << p;
      worst = std::max(worst, diff);
    }
  }
  RecordProperty("max_pixel_difference", sci(worst));
}

}  // namespace
}  // namespace vob
