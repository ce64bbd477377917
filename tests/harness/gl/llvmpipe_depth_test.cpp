// llvmpipe's depth model (harness/raster/llvmpipe_depth.h) against llvmpipe's own depth
// buffer: triangles on the 1/256-pixel grid with random window depths are drawn by OSMesa
// (depth test GL_ALWAYS, so every pixel holds the last triangle's depth) into an item
// buffer and a DEPTH24_STENCIL8 buffer, read back as 24-bit values and compared pixel by
// pixel with the model. The framebuffer is large (1000 x 1000) so that triangles lie far
// from its origin, where the plane's value at the origin is large; steep and nearly
// edge-on triangles make the gradients large. A plane in doubles through the same float
// window positions is counted too: it must differ somewhere, or the test could not fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "harness/gl/shader_program.h"
#include "harness/gl/window_vertices.h"
#include "harness/raster/llvmpipe_depth.h"
#include "harness/raster/raster_rule.h"
#include "tests/harness/gl/id_framebuffer.h"

using namespace vob;

namespace {

constexpr int W = 1000, H = 1000;

struct Tri {
  double x[3], y[3], depth[3];  // window positions on the 1/256 grid, window depths in (0, 1)
};

const gl::ShaderFile kVert{"tests/depth.vert",
                           "#version 330 core\nlayout(location = 0) in vec3 p;\nlayout(location = 1) in uint id;\n"
                           "flat out uint v_id;\nvoid main() { gl_Position = vec4(p, 1.0); v_id = id; }\n"};
const gl::ShaderFile kFrag{"tests/depth.frag",
                           "#version 330 core\nflat in uint v_id;\nlayout(location = 0) out uint colour;\n"
                           "void main() { colour = v_id + 1u; }\n"};

struct Vertex {
  float x, y, z;
  uint32_t id;
};

// Item buffer (last triangle id + 1) and 24-bit depth of `tris` drawn in order by llvmpipe.
void draw_gl(const std::vector<Tri>& tris, std::vector<uint32_t>& item, std::vector<uint32_t>& depth) {
  gl::Functions& f = test::llvmpipe();
  static GLuint program = gl::link_program(f, {gl::shader_stage(GL_VERTEX_SHADER, {kVert}),
                                               gl::shader_stage(GL_FRAGMENT_SHADER, {kFrag})});
  const gl::Pow2Viewport vp(W, H);
  const auto v = test::triangle_vertices<Vertex>(tris, vp, [&](auto n, size_t t, int k) {
    return Vertex{n[0], n[1], float(2 * tris[t].depth[k] - 1), uint32_t(t)};
  });
  test::IdFramebuffer fb(f, program, W, H, vp.w, vp.h, v, 3);
  ASSERT_TRUE(fb.complete());
  f.glEnable(GL_DEPTH_TEST);
  f.glDepthFunc(GL_ALWAYS);
  fb.draw();
  item = fb.read_items();
  depth = fb.read_depth24();
  ASSERT_EQ(f.glGetError(), GLenum(GL_NO_ERROR));
}

// The triangle's float window positions in the order llvmpipe's setup receives them.
void setup_order(const Tri& t, float x[3], float y[3], float z[3]) {
  int64_t fx[3], fy[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = float(t.x[k]), y[k] = float(t.y[k]), z[k] = llvmpipe_window_z(t.depth[k]);
    fx[k] = gl_snap(t.x[k]), fy[k] = gl_snap(t.y[k]);
  }
  if ((fx[0] - fx[1]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[0] - fy[1]) < 0)
    std::swap(x[0], x[1]), std::swap(y[0], y[1]), std::swap(z[0], z[1]);
}

// The same plane through the same float positions, evaluated in doubles at the pixel.
int64_t double_plane24(const float x[3], const float y[3], const float z[3], int px, int py) {
  const double ex1 = double(x[1]) - x[0], ey1 = double(y[1]) - y[0], ez1 = double(z[1]) - z[0];
  const double ex2 = double(x[2]) - x[0], ey2 = double(y[2]) - y[0], ez2 = double(z[2]) - z[0];
  const double det = ex1 * ey2 - ex2 * ey1;
  const double gx = (ez1 * ey2 - ez2 * ey1) / det, gy = (ez2 * ex1 - ez1 * ex2) / det;
  const double zz = z[0] + gx * (px + 0.5 - x[0]) + gy * (py + 0.5 - y[0]);
  return gl_depth24(zz);
}

struct Rng {
  uint64_t s;
  uint32_t next() { return uint32_t((s = s * 6364136223846793005ull + 1442695040888963407ull) >> 33); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * (next() / 2147483648.0); }
};

// kind 0: random sizes anywhere; 1: small and steep (depth across the whole range over a few
// pixels); 2: nearly edge-on slivers; 3: far from the origin (the top right corner), steep;
// 4: vertices on pixel centres (edges through them).
std::vector<Tri> triangles(int kind, uint64_t seed, int n) {
  Rng r{seed * 104729 + uint64_t(kind)};
  std::vector<Tri> out;
  auto grid = [](double v, int lim) { return gl_unsnap(gl_snap(std::clamp(v, 0.25, lim - 0.25))); };
  for (int i = 0; i < n; ++i) {
    const double cx = kind == 3 ? r.uniform(800, W) : r.uniform(0, W);
    const double cy = kind == 3 ? r.uniform(800, H) : r.uniform(0, H);
    const double spread = kind == 0 ? r.uniform(2, 300) : kind == 2 ? r.uniform(20, 300) : r.uniform(2, 20);
    Tri t;
    for (int k = 0; k < 3; ++k) {
      t.x[k] = grid(cx + r.uniform(-spread, spread), W);
      t.y[k] = grid(cy + r.uniform(-spread, spread), H);
      t.depth[k] = kind == 0 ? r.uniform(0.3, 0.99) : r.uniform(0.01, 0.99);
      if (kind == 4) t.x[k] = std::floor(t.x[k]) + 0.5, t.y[k] = std::floor(t.y[k]) + 0.5;
    }
    if (kind == 2) {  // the third vertex within 1/50 pixel of the first edge
      const double a = r.uniform(0.2, 0.8);
      t.x[2] = grid(t.x[0] + a * (t.x[1] - t.x[0]) + r.uniform(-0.02, 0.02), W);
      t.y[2] = grid(t.y[0] + a * (t.y[1] - t.y[0]) + r.uniform(-0.02, 0.02), H);
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace

TEST(LlvmpipeDepth, ModelMatchesTheDepthBufferBitForBit) {
  try {
    test::llvmpipe();
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << "no OSMesa context: " << e.what();
  }
  const char* names[] = {"random", "steep", "edge-on", "far", "centres"};
  int64_t sampled = 0, mismatched = 0, double_differs = 0, max_double_diff = 0;
  for (int kind = 0; kind < 5; ++kind) {
    int64_t kind_sampled = 0, kind_mismatched = 0;
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      const std::vector<Tri> tris = triangles(kind, seed, kind == 0 ? 60 : 600);
      std::vector<uint32_t> item, depth;
      draw_gl(tris, item, depth);
      for (int py = 0; py < H; ++py)
        for (int px = 0; px < W; ++px) {
          const size_t p = size_t(py) * W + px;
          if (item[p] == 0) continue;
          float x[3], y[3], z[3];
          setup_order(tris[item[p] - 1], x, y, z);
          const int64_t model = llvmpipe_depth24(llvmpipe_depth_plane(x, y, z), px, py);
          const int64_t dbl = double_plane24(x, y, z, px, py);
          ++kind_sampled;
          double_differs += dbl != int64_t(depth[p]);
          max_double_diff = std::max(max_double_diff, std::abs(dbl - int64_t(depth[p])));
          if (model != int64_t(depth[p]) && ++kind_mismatched <= 3)
            ADD_FAILURE() << names[kind] << " seed " << seed << " pixel " << px << "," << py << ": llvmpipe "
                          << depth[p] << ", model " << model;
        }
    }
    std::printf("%-8s %lld pixels, %lld mismatching\n", names[kind], (long long)kind_sampled,
                (long long)kind_mismatched);
    sampled += kind_sampled;
    mismatched += kind_mismatched;
  }
  std::printf("llvmpipe depth: %lld pixels sampled, %lld mismatches (a double plane: %lld differ, by up to %lld)\n",
              (long long)sampled, (long long)mismatched, (long long)double_differs, (long long)max_double_diff);
  EXPECT_EQ(mismatched, 0);
  EXPECT_GT(sampled, 1000000);
  EXPECT_GT(double_differs, 0);  // the test can fail: a plane in doubles is not llvmpipe's depth
}
