// The gl sampling rule (harness/raster/raster_rule.h) against llvmpipe's own coverage:
// random triangles are drawn with OSMesa into an item buffer (last triangle id + 1) and a
// stencil count of the triangles covering each pixel, read back and compared pixel by
// pixel with the harness rasterizer under the rule. Window positions reach llvmpipe
// exactly (harness/gl/window_vertices.h). "raw" triangles hand llvmpipe unsnapped floats,
// so its own snapping is tested too (including ties halfway between 1/256 steps); the
// others are on the 1/256 grid or on pixel centres, so many centres lie exactly on edges
// and vertices, where only the fill rule decides.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "harness/gl/shader_program.h"
#include "harness/gl/window_vertices.h"
#include "harness/raster/polygon_raster.h"
#include "tests/harness/gl/id_framebuffer.h"

using namespace vob;

namespace {

constexpr int W = 100, H = 75;

struct Tri {
  double x[3], y[3];
};

const gl::ShaderFile kVert{"tests/coverage.vert",
                           "#version 330 core\nlayout(location = 0) in vec2 p;\nlayout(location = 1) in uint id;\n"
                           "flat out uint v_id;\nvoid main() { gl_Position = vec4(p, 0.0, 1.0); v_id = id; }\n"};
const gl::ShaderFile kFrag{"tests/coverage.frag",
                           "#version 330 core\nflat in uint v_id;\nlayout(location = 0) out uint colour;\n"
                           "void main() { colour = v_id + 1u; }\n"};

struct Vertex {
  float x, y;
  uint32_t id;
};

// Item buffer and coverage count of `tris` drawn in order by llvmpipe.
void draw_gl(const std::vector<Tri>& tris, std::vector<uint32_t>& colour, std::vector<uint8_t>& count) {
  gl::Functions& f = test::llvmpipe();
  static GLuint program = gl::link_program(f, {gl::shader_stage(GL_VERTEX_SHADER, {kVert}),
                                               gl::shader_stage(GL_FRAGMENT_SHADER, {kFrag})});
  const gl::Pow2Viewport vp(W, H);
  const auto v = test::triangle_vertices<Vertex>(tris, vp, [](auto n, size_t t, int) {
    return Vertex{n[0], n[1], uint32_t(t)};
  });
  test::IdFramebuffer fb(f, program, W, H, vp.w, vp.h, v, 2);
  ASSERT_TRUE(fb.complete());
  f.glDisable(GL_DEPTH_TEST);
  f.glEnable(GL_STENCIL_TEST);
  f.glStencilFunc(GL_ALWAYS, 0, ~0u);
  f.glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  fb.draw();
  colour = fb.read_items();
  count = fb.read_stencil();
  ASSERT_EQ(f.glGetError(), GLenum(GL_NO_ERROR));
}

// The same under the rule: the window positions go to the rasterizer as projected
// vertices (the 3D points only give it a plane for depths).
void draw_rule(const std::vector<Tri>& tris, std::vector<uint32_t>& colour, std::vector<uint8_t>& count,
               RasterRule rule = RasterRule::gl) {
  Camera cam;
  cam.eye = {W / 2.0, H / 2.0, 10};
  cam.target = {W / 2.0, H / 2.0, 0};
  cam.up = {0, 1, 0};
  cam.ortho = true;
  cam.ortho_height = H;
  cam.width = W;
  cam.height = H;
  const SampleFrame frame(cam, 1, rule);
  colour.assign(size_t(W) * H, 0);
  count.assign(size_t(W) * H, 0);
  for (size_t t = 0; t < tris.size(); ++t) {
    Vec3 p[3];
    ProjectedVertex q[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = {tris[t].x[k], tris[t].y[k], 0};
      q[k] = {tris[t].x[k], tris[t].y[k], true};
    }
    PolygonRaster r;
    if (!r.setup(frame, p, 3, q)) continue;
    r.scan(frame.bounds(), [&](int sx, int sy, double) {
      colour[size_t(sy) * W + sx] = uint32_t(t) + 1;
      ++count[size_t(sy) * W + sx];
    });
  }
}

struct Rng {
  uint64_t s;
  uint32_t next() { return uint32_t((s = s * 6364136223846793005ull + 1442695040888963407ull) >> 33); }
  int in(int lo, int hi) { return lo + int(next() % uint32_t(hi - lo + 1)); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * (next() / 2147483648.0); }
};

// kind 0: raw floats; 1: on the 1/256 grid; 2: vertices on pixel centres (edges through
// centres); 3: raw, at ties halfway between grid steps; 4: slivers and tiny triangles on the grid.
std::vector<Tri> triangles(int kind, uint64_t seed, int n) {
  Rng r{seed * 7919 + uint64_t(kind)};
  std::vector<Tri> out;
  auto coord = [&](double c, int lim, double spread) -> double {
    const double v = std::min(std::max(c + r.uniform(-spread, spread), 0.25), lim - 0.25);
    switch (kind) {
      case 0: return double(float(v));
      case 2: return std::floor(v) + 0.5;
      case 3: return gl_unsnap(int64_t(std::floor((v - 0.5) * 256))) + 1.0 / 512;
      default: return gl_unsnap(gl_snap(v));
    }
  };
  for (int i = 0; i < n; ++i) {
    const double cx = r.uniform(0, W), cy = r.uniform(0, H);
    const double spread = kind == 4 ? (i % 2 ? 1.5 : 12) : r.uniform(2, 25);
    Tri t;
    for (int k = 0; k < 3; ++k) t.x[k] = coord(cx, W, spread), t.y[k] = coord(cy, H, spread);
    if (kind == 4 && i % 2 == 0) {  // a sliver: the third vertex near the first edge
      const double a = r.uniform(0.2, 0.8);
      t.x[2] = coord(t.x[0] + a * (t.x[1] - t.x[0]), W, 0.02);
      t.y[2] = coord(t.y[0] + a * (t.y[1] - t.y[0]), H, 0.02);
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace

TEST(LlvmpipeCoverage, GlRuleMatchesEveryPixel) {
  try {
    test::llvmpipe();
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << "no OSMesa context: " << e.what();
  }
  int64_t sampled = 0, covered = 0, colour_mismatch = 0, count_mismatch = 0, exact_mismatch = 0;
  const char* names[] = {"raw", "grid", "centres", "ties", "slivers"};
  for (int kind = 0; kind < 5; ++kind) {
    int64_t kind_mismatch = 0;
    for (uint64_t seed = 1; seed <= 8; ++seed) {
      const std::vector<Tri> tris = triangles(kind, seed, 120);
      std::vector<uint32_t> gc, rc;
      std::vector<uint8_t> gn, rn;
      draw_gl(tris, gc, gn);
      draw_rule(tris, rc, rn);
      std::vector<uint32_t> ec;
      std::vector<uint8_t> en;
      draw_rule(tris, ec, en, RasterRule::exact);  // the test can fail: the exact rule differs
      for (size_t p = 0; p < gc.size(); ++p) exact_mismatch += gc[p] != ec[p] || gn[p] != en[p];
      for (size_t p = 0; p < gc.size(); ++p) {
        ++sampled;
        covered += rn[p] > 0;
        colour_mismatch += gc[p] != rc[p];
        count_mismatch += gn[p] != rn[p];
        kind_mismatch += gc[p] != rc[p] || gn[p] != rn[p];
        if ((gc[p] != rc[p] || gn[p] != rn[p]) && kind_mismatch < 4)
          ADD_FAILURE() << names[kind] << " seed " << seed << " pixel " << p % W << "," << p / W << ": llvmpipe id "
                        << gc[p] << " count " << int(gn[p]) << ", rule id " << rc[p] << " count " << int(rn[p]);
      }
    }
    std::printf("%-8s %lld mismatching pixels\n", names[kind], (long long)kind_mismatch);
  }
  std::printf("llvmpipe coverage: %lld pixels sampled (%lld covered), %lld item and %lld count mismatches "
              "(exact rule: %lld pixels differ)\n",
              (long long)sampled, (long long)covered, (long long)colour_mismatch, (long long)count_mismatch,
              (long long)exact_mismatch);
  EXPECT_EQ(colour_mismatch, 0);
  EXPECT_EQ(count_mismatch, 0);
  EXPECT_GT(covered, sampled / 3);
  EXPECT_GT(exact_mismatch, 0);
}
