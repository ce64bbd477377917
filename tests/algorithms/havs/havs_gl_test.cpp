// HAVS: the OpenGL fragment-shader k-buffer (algorithms/havs/gl/gl_kbuffer.h) against the
// software k-buffer on the same face order. In serialized mode (no two fragments of a pixel in
// one draw, memory barriers between draws) the read-modify-write cannot race, so the images
// must agree up to rasterization rounding: coverage of pixel centres within llvmpipe's
// 1/256-pixel vertex snapping of an edge, float exp, and double dot products.
// Tolerance at 8 bits per view: at most 1% of the pixels differ, and the RMS difference
// over all channels is at most 1 (in 1/255 units); fragment counts agree within 0.5%.
// The tests skip (GTEST_SKIP with the reason) only when no GL 4.5 context can be made.
#include <gtest/gtest.h>

#include "harness/raster/raster_rule.h"

#include <cstdio>

#include "algorithms/havs/gl/gl_kbuffer.h"
#include "algorithms/havs/havs_frame.h"
#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/gl/osmesa_context.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"
#include "tests/algorithms/havs/havs_views.h"
#include "tests/support/test_util.h"

namespace vob {
namespace {

using test::small_mesh;

constexpr int kViews = test::kHavsViews, kSize = 128;

Camera view_of(const Scene& s, int i) { return test::havs_view(s, i, kSize); }

class HavsGl : public ::testing::TestWithParam<std::string> {};

TEST_P(HavsGl, SerializedMatchesSoftware) {
  const Scene scene = small_mesh(GetParam());
  const havs::FaceData fd = havs::build_face_data(scene);
  std::unique_ptr<havs::GlKBuffer> gl;
  try {
    gl = std::make_unique<havs::GlKBuffer>(fd);
  } catch (const havs::GlUnavailable& e) {
    GTEST_SKIP() << "no GL context: " << e.what();
  }
  int64_t covered = 0, differing = 0, differing_rule = 0;
  for (int v = 0; v < kViews; v += 3) {
    const Camera cam = view_of(scene, v);
    const std::vector<int32_t> order = test::havs_face_order(fd, cam);
    for (int k : {1, 2, 6}) {
      Image sw, hw;
      const havs::RenderStats rs = havs::render_kbuffer(fd, cam, order, k, sw);
      const havs::GlFrameStats gs = gl->render(cam, order, k, havs::GlDrawMode::Serialized, hw);
      ASSERT_GT(rs.fragments, 0);
      EXPECT_NEAR(double(gs.fragments), double(rs.fragments), 0.005 * rs.fragments)
          << "view " << v << " k " << k;
      EXPECT_GT(gs.draws, 1);
      const havs::ImageCompare8 c = havs::compare_8bit(hw, sw);
      EXPECT_LE(c.differing, c.pixels / 100) << "view " << v << " k " << k;
      EXPECT_LE(c.rms, 1.0) << "view " << v << " k " << k;
      differing += c.differing;
      // Under the gl sampling rule the software k-buffer covers llvmpipe's pixels: what
      // differs is only where llvmpipe's own float vertex transform snaps otherwise.
      Image sw_rule;
      havs::render_kbuffer(fd, cam, order, k, sw_rule, nullptr, RasterRule::gl);
      const havs::ImageCompare8 cr = havs::compare_8bit(hw, sw_rule);
      EXPECT_LE(cr.differing, c.differing) << "view " << v << " k " << k;
      differing_rule += cr.differing;
      for (size_t p = 0; p < sw.rgb.size(); p += 3) covered += sw.rgb[p] + sw.rgb[p + 1] + sw.rgb[p + 2] > 0;
    }
  }
  std::printf("%s: %ld of %ld covered pixel-frames differ at 8 bits; %ld against the software k-buffer under the gl rule\n",
              GetParam().c_str(), long(differing), long(covered), long(differing_rule));
  EXPECT_LT(differing_rule * 4, differing + 4);  // the rule explains most differences
  // The images are not blank: most covered pixels agree exactly at 8 bits.
  EXPECT_GT(covered, 0);
  EXPECT_LT(differing * 20, covered);
}

INSTANTIATE_TEST_SUITE_P(Meshes, HavsGl, ::testing::Values("gap", "helix"));

// The orderer with backend=gl: same face order, same cell order as the software backend, and
// its image through the harness equals the software's within the tolerance above.
TEST(HavsGlOrderer, BackendGlThroughRegistry) {
  const Scene scene = small_mesh("gap");
  const Camera cam = view_of(scene, 5);
  PreparedOrderer sw = prepare_orderer("havs:k=2,analyze=false", scene);
  std::unique_ptr<PreparedOrderer> gl;
  try {
    gl = std::make_unique<PreparedOrderer>(
        prepare_orderer("havs:k=2,analyze=false,backend=gl,gl_draw=serialized", scene));
  } catch (const InputError& e) {
    GTEST_SKIP() << "no GL context: " << e.what();
  }
  PhaseClock ca, cb;
  const Ordering a = sw.orderer->order(cam, ca);
  const Ordering b = gl->orderer->order(cam, cb);
  EXPECT_EQ(a.order, b.order);
  ASSERT_TRUE(b.counters.count("havs_gl_fragments"));
  EXPECT_NEAR(b.counters.at("havs_gl_fragments"), a.counters.at("havs_fragments"),
              0.005 * a.counters.at("havs_fragments"));
  EXPECT_EQ(resolved_parameters(gl->spec).value("backend", ""), "gl");  // what the record says
}

// An impossible context request is one clear error line, not a crash.
TEST(HavsGlContext, ImpossibleRequestIsOneLine) {
  gl::ContextRequest r;
  r.major = 9;
  r.minor = 9;
  try {
    gl::OsmesaContext ctx(r);
    FAIL() << "a GL 9.9 context was created";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("OSMesa"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace vob
