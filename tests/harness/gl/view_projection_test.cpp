// The GL plugins' view-projection matrix (harness/gl/view_projection.h) against the
// harness' own projection: a vertex must land where SampleFrame::project puts it, or the
// GL images and the oracle would disagree about coverage.
#include <gtest/gtest.h>

#include <array>

#include "harness/gl/view_projection.h"
#include "harness/raster/sample_frame.h"

using namespace vob;

namespace {

struct Clip {
  double x, y, z, w;
};
Clip apply(const std::array<double, 16>& m, Vec3 p) {
  const double v[4] = {p.x, p.y, p.z, 1.0};
  double out[4] = {0, 0, 0, 0};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[r] += m[c * 4 + r] * v[c];
  return {out[0], out[1], out[2], out[3]};
}

Camera camera(bool ortho) {
  Camera c;
  c.eye = {3, -1.5, 2};
  c.target = {0.2, 0.1, -0.3};
  c.up = {0, 0, 1};
  c.width = 96;
  c.height = 64;
  c.fov_deg = 35;
  c.ortho = ortho;
  c.ortho_height = 2.5;
  return c;
}

const Vec3 kPoints[] = {{0, 0, 0}, {0.7, -0.4, 0.3}, {-0.5, 0.6, -0.8}, {0.9, 0.9, 0.9}, {-1, -0.2, 0.4}};

}  // namespace

TEST(ViewProjection, MapsPointsToSampleFramePixels) {
  for (bool ortho : {false, true})
    for (bool flip : {false, true}) {
      const Camera view = camera(ortho);
      const SampleFrame frame(view, 1);
      gl::ProjectionOptions opt;
      opt.origin = {0.25, -0.5, 1.0};
      opt.flip_y = flip;
      const auto m = gl::view_projection(view, opt);
      for (const Vec3& p : kPoints) {
        double x, y, zc;
        ASSERT_TRUE(frame.project(p, x, y, zc));
        const Clip c = apply(m, p - opt.origin);
        ASSERT_GT(c.w, 0);
        EXPECT_DOUBLE_EQ(c.w, ortho ? 1.0 : zc);
        EXPECT_EQ(c.z, 0.0);  // no depth requested: nothing is clipped by near or far
        const double wx = (c.x / c.w + 1) * 0.5 * view.width;
        const double wy = (c.y / c.w + 1) * 0.5 * view.height;
        EXPECT_NEAR(wx, x, 1e-9) << "ortho " << ortho;
        EXPECT_NEAR(flip ? view.height - wy : wy, y, 1e-9) << "ortho " << ortho;
      }
    }
}

TEST(ViewProjection, DepthRangeMapsNearAndFarToMinusOneAndOne) {
  for (bool ortho : {false, true}) {
    const Camera view = camera(ortho);
    gl::ProjectionOptions opt;
    opt.depth = true;
    opt.near = 1.5;
    opt.far = 6.0;
    const auto m = gl::view_projection(view, opt);
    for (double z : {opt.near, 0.5 * (opt.near + opt.far), opt.far}) {
      const Clip c = apply(m, view.eye + view.forward() * z);
      const double expect = ortho ? 2 * (z - opt.near) / (opt.far - opt.near) - 1
                                  : (z * (opt.far + opt.near) - 2 * opt.far * opt.near) /
                                        (z * (opt.far - opt.near));
      EXPECT_NEAR(c.z / c.w, expect, 1e-12) << "ortho " << ortho << " z " << z;
    }
  }
}
