#include <gtest/gtest.h>

#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"

using namespace vob;

TEST(Camera, ProjectAndRayAgreeAtPixelCentres) {
  for (bool ortho : {false, true}) {
    Camera c;
    c.eye = {3, 1, 2};
    c.target = {0, 0, 0};
    c.up = {0, 0, 1};
    c.width = 64;
    c.height = 48;
    c.ortho = ortho;
    c.ortho_height = 3;
    const Ray r = c.pixel_ray(10, 37);
    const Vec3 p = r.origin + r.dir * 2.5;
    double wx, wy, d;
    ASSERT_TRUE(c.project(p, wx, wy, d));
    EXPECT_NEAR(wx, 10.5, 1e-9);
    EXPECT_NEAR(wy, 37.5, 1e-9);
    EXPECT_NEAR(c.depth(p), 2.5 + (ortho ? dot(r.origin - c.eye, c.forward()) : 0), 1e-9);
  }
}

TEST(Camera, JsonRoundTrip) {
  Camera c;
  c.ortho = true;
  c.ortho_height = 7;
  c.width = 300;
  c.height = 200;
  Camera d = Camera::from_json(c.to_json());
  EXPECT_EQ(d.to_json(), c.to_json());
}

TEST(Camera, ImpossibleCameraIsRejected) {
  Camera c;
  c.target = c.eye;
  EXPECT_THROW(c.validate(), InputError);
}

TEST(ViewSet, FibonacciViewsAreDeterministicAndOnTheSphere) {
  Aabb b;
  b.add({-1, -1, -1});
  b.add({1, 2, 3});
  auto v1 = fibonacci_views(b, 14);
  auto v2 = fibonacci_views(b, 14);
  ASSERT_EQ(v1.size(), 14u);
  for (int i = 0; i < 14; ++i) {
    EXPECT_EQ(v1[i].to_json(), v2[i].to_json());
    EXPECT_NEAR(length(v1[i].eye - b.center()), kViewDistance * b.radius(), 1e-9);
    EXPECT_NO_THROW(v1[i].validate());
  }
  EXPECT_THROW(fibonacci_view(b, 14, 14), InputError);
}
