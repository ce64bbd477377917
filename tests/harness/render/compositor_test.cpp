#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>
#include <vector>

#include <unistd.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

TEST(Compositor, ExactOrderEqualsExactRender) {
  const int n = 4;
  const Scene s = test::kuhn_block_scene(n);
  ViewOptions vo;
  vo.width = 80;
  vo.height = 60;
  for (int v : {0, 6, 11}) {
    const Camera cam = fibonacci_view(s.bounds(), 14, v, vo);
    auto order = test::tet_block_exact_order(s.mesh(), n, cam);
    const Image exact = render_exact(s, cam);
    const Image in_order = render_in_order(s, cam, order);
    const ImageError e = image_error(in_order, exact);
    EXPECT_EQ(e.rmse, 0.0);
    EXPECT_EQ(e.max_error, 0.0);
    EXPECT_EQ(e.pixels_off, 0);
    // The mesh is visible, with an optical depth that neither vanishes nor saturates.
    float brightest = 0;
    for (float x : exact.rgb) brightest = std::max(brightest, x);
    EXPECT_GT(brightest, 0.3f);
    EXPECT_LT(brightest, 1.0f);
    std::reverse(order.begin(), order.end());
    const ImageError r = image_error(render_in_order(s, cam, order), exact);
    EXPECT_GT(r.pixels_off, 100);
    EXPECT_GT(r.rmse, 0.005);
    EXPECT_GT(r.max_error, 1.0 / 255);
  }
}

TEST(Compositor, TrianglesAndVoxels) {
  TriangleSoup soup;
  soup.points = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1.5}};
  soup.tris = {{0, 1, 2}, {3, 4, 5}};
  const Scene t = Scene::from_soup("two", soup);
  const Camera cam = test::test_camera({0.3, -2, 5}, {0, 0, 0.5}, 48, 48);
  const Image ex = render_exact(t, cam);
  EXPECT_EQ(image_error(render_in_order(t, cam, {0, 1}), ex).pixels_off, 0);
  EXPECT_GT(image_error(render_in_order(t, cam, {1, 0}), ex).pixels_off, 50);

  VoxelGrid g;
  g.dims = {4, 4, 4};
  g.values.resize(g.num_voxels());
  for (size_t i = 0; i < g.values.size(); ++i) g.values[i] = float(i % 7);
  g.threshold = 0.5f;
  const Scene v = Scene::from_grid("vox", g);
  const Camera vc = fibonacci_view(v.bounds(), 14, 2, {.width = 48, .height = 48});
  std::vector<int32_t> order = significant_voxels(g);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
    return vc.depth(g.centre_of(a)) > vc.depth(g.centre_of(b));
  });
  const Image vex = render_exact(v, vc);
  EXPECT_LT(image_error(render_in_order(v, vc, order), vex).max_error, 1e-6);
  std::reverse(order.begin(), order.end());
  EXPECT_GT(image_error(render_in_order(v, vc, order), vex).pixels_off, 50);
}

TEST(Compositor, DifferenceImageAndErrors) {
  Image a{2, 1, {0.0f, 0.0f, 0.0f, 0.8f, 0.4f, 0.2f}};
  Image b = a;
  b.rgb[3] = 0.7f;
  const ImageError e = image_error(b, a);
  EXPECT_EQ(e.pixels_off, 1);
  EXPECT_NEAR(e.max_error, 0.1, 1e-6);
  EXPECT_NEAR(e.rmse, std::sqrt(0.01 / 6), 1e-6);
  const Image d = difference_image(b, a);
  EXPECT_EQ(d.rgb[3], 1.0f);
  EXPECT_NEAR(d.rgb[4], 1.0f, 0);
  EXPECT_NEAR(d.rgb[0], 0.0f, 0);
  const Image c{1, 1, {0.5f, 0.5f, 0.5f}};
  EXPECT_THROW(image_error(a, c), InputError);
}

TEST(Compositor, PngIsWrittenAndReadable) {
  // A 3x2 image with a distinct bottom-left pixel: row 0 is the bottom row.
  Image img{3, 2, std::vector<float>(18, 0.0f)};
  img.rgb[0] = 1.0f;                  // (0, 0) red, bottom left
  img.rgb[(1 * 3 + 2) * 3 + 2] = 1.0f;  // (2, 1) blue, top right
  const auto dir = std::filesystem::temp_directory_path() / ("vob_png_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "img.png").string();
  write_png(img, path);
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temp left
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* d = reader->GetOutput();
  int dims[3];
  d->GetDimensions(dims);
  ASSERT_EQ(dims[0], 3);
  ASSERT_EQ(dims[1], 2);
  auto px = [&](int x, int y, int c) {
    return int(static_cast<unsigned char*>(d->GetScalarPointer(x, y, 0))[c]);
  };
  EXPECT_EQ(px(0, 0, 0), 255);
  EXPECT_EQ(px(0, 0, 2), 0);
  EXPECT_EQ(px(2, 1, 2), 255);
  EXPECT_EQ(px(2, 1, 0), 0);
  // And a rendered image.
  const Scene s = test::kuhn_block_scene(2);
  const Camera cam = fibonacci_view(s.bounds(), 14, 1, {.width = 32, .height = 24});
  write_png(render_exact(s, cam), path);
  reader->Modified();
  reader->Update();
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 32);
  EXPECT_EQ(dims[1], 24);
  EXPECT_THROW(write_png(img, (dir / "missing" / "x.png").string()), InputError);
  std::filesystem::remove_all(dir);
}
