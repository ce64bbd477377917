// OpenGL (OSMesa) and software backends of the layer extraction.
//
// The GL backend hands llvmpipe window positions snapped by the gl sampling rule
// (harness/raster/raster_rule.h), so the software backend under that rule rasterizes
// exactly what llvmpipe does: the item buffers, the stencil counts and the layers agree
// pixel for pixel, on dyadic orthographic scenes with many pixel centres exactly on edges
// (where only the fill rule decides) and on perspective views of closed surfaces (where
// depths are interpolated by llvmpipe in floats and compared in 24 bits, by the software
// backend in doubles rounded to 24 bits; the later passes of a few views differ where
// llvmpipe's float interpolation reorders close depths). Under the exact rule the software backend
// differs from GL at pixel centres within 1/256 pixel of an edge (the snapping).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "algorithms/stencil/gl_backend.h"
#include "algorithms/stencil/layer_extraction.h"
#include "algorithms/stencil/software_backend.h"
#include "datasets/datasets.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;
using namespace vob::stencil;

namespace {

void polygons(const Scene& s, std::vector<Vec3>& pts, std::vector<int8_t>& sizes) {
  const TriangleSoup& soup = s.soup();
  pts.assign(4 * soup.num_triangles(), Vec3{});
  sizes.assign(soup.num_triangles(), 3);
  for (size_t t = 0; t < soup.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) pts[4 * t + k] = soup.points[soup.tris[t][k]];
}

std::unique_ptr<GlBackend> gl_or_skip() {
  try {
    return std::make_unique<GlBackend>();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "OSMesa context: " << e.what();
    return nullptr;
  }
}



struct Buffers {
  std::vector<uint32_t> colour;
  std::vector<uint8_t> stencil;
};

// The candidate and depth-complexity passes of all primitives on one backend.
std::pair<Buffers, Buffers> all_passes(LayerBackend& be, int32_t n, const Camera& view) {
  std::vector<int32_t> all(static_cast<size_t>(n)), rev;
  for (int32_t i = 0; i < n; ++i) all[size_t(i)] = i;
  rev.assign(all.rbegin(), all.rend());
  const size_t px = size_t(view.width) * view.height;
  const PixelRect r{0, 0, view.width, view.height};
  Buffers c{std::vector<uint32_t>(px), {}}, g{std::vector<uint32_t>(px), std::vector<uint8_t>(px)};
  be.begin_frame(view);
  be.render_candidates(all);
  be.finish();
  be.read_colour(r, c.colour.data());
  be.render_complexity(rev);
  be.finish();
  be.read_colour(r, g.colour.data());
  be.read_stencil(r, g.stencil.data());
  return {c, g};
}

LayerResult layers(LayerBackend& be, int32_t n, const Camera& view, bool blocked) {
  LayerExtractor x;
  LayerResult r;
  PhaseClock c;
  be.begin_frame(view);
  x.run(be, n, view, ExtractOptions{blocked, 16}, c, r);
  return r;
}

// Triangles and quads with vertices on the half-pixel grid, seen orthographically with one
// world unit per pixel, edges at most 32 pixels long. Every vertex projects exactly (so
// llvmpipe's snapping changes nothing), and a pixel centre is either exactly on an edge
// line or at least 1/128 pixel from it (edge functions are multiples of 1/4), far beyond
// llvmpipe's fixed-point error; many centres lie exactly on edges, where the fill rule
// decides. Everything lies inside the viewport: llvmpipe clips triangles that leave it, and
// the clipped vertices are no longer on the grid (views of whole models never clip). Each
// primitive lies in its own depth slab (tilted inside it): the scene is
// acyclic and depths are far apart in 24 bits.
void dyadic_scene(int size, uint64_t seed, std::vector<Vec3>& pts, std::vector<int8_t>& sizes, Camera& view) {
  uint64_t st = seed;
  auto next = [&]() {
    st = st * 6364136223846793005ull + 1442695040888963407ull;
    return uint32_t(st >> 33);
  };
  auto half = [&](double lo, double hi) { return lo + double(next() % uint32_t((hi - lo) * 2)) / 2.0; };
  pts.clear();
  sizes.clear();
  int slab = 0;
  auto add = [&](std::initializer_list<Vec3> v) {
    for (const Vec3& p : v) pts.push_back(p + Vec3{0, 0, slab * 8.0});
    for (size_t k = v.size(); k < 4; ++k) pts.push_back(Vec3{});
    sizes.push_back(int8_t(v.size()));
    ++slab;
  };
  const double S = size;
  for (int i = 0; i < 150; ++i) {
    const double cx = half(0, S), cy = half(0, S), r = 11;
    Vec3 v[3];
    double area = 0;
    do {
      for (Vec3& p : v)
        p = {std::clamp(cx + half(-r, r), 0.0, S), std::clamp(cy + half(-r, r), 0.0, S), half(0, 4)};
      area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    } while (area == 0);
    add({v[0], v[1], v[2]});
  }
  for (int i = 0; i < 12; ++i) {  // two triangles sharing a diagonal through pixel centres
    const double x0 = std::floor(half(0, S - 20)) + 0.5, y0 = std::floor(half(0, S - 20)) + 0.5;
    const double w = std::floor(half(4, 20)), z = half(0, 2);
    add({{x0, y0, z}, {x0 + w, y0, z}, {x0 + w, y0 + w, z}});
    --slab;
    add({{x0, y0, z}, {x0 + w, y0 + w, z}, {x0, y0 + w, z}});
  }
  for (int i = 0; i < 12; ++i) {  // planar quads (both backends split them alike)
    const double x0 = half(0, S - 20), y0 = half(0, S - 20), z = half(0, 2);
    add({{x0, y0, z}, {x0 + half(6, 18), y0 + 0.5, z}, {x0 + half(10, 20), y0 + half(10, 20), z},
         {x0 + 0.5, y0 + half(6, 18), z}});
  }
  view = Camera{};
  view.eye = {S / 2, S / 2, 4000};
  view.target = {S / 2, S / 2, 0};
  view.up = {0, 1, 0};
  view.ortho = true;
  view.ortho_height = S;
  view.width = view.height = size;
}

// Smallest nonzero distance (pixels) from a pixel centre to an edge line of the scene's
// triangles (quads: their split triangles), and how many centres lie exactly on one.
std::pair<double, int64_t> edge_margin(const std::vector<Vec3>& pts, const std::vector<int8_t>& sizes, int size) {
  double margin = 1e300;
  int64_t on_edge = 0;
  auto edge = [&](const Vec3& a, const Vec3& b) {
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double e = (b.x - a.x) * (y + 0.5 - a.y) - (b.y - a.y) * (x + 0.5 - a.x);
        if (e == 0)
          ++on_edge;
        else
          margin = std::min(margin, std::abs(e) / len);
      }
  };
  for (size_t i = 0; i < sizes.size(); ++i) {
    const Vec3* p = &pts[4 * i];
    for (int k = 0; k < sizes[i]; ++k) edge(p[k], p[(k + 1) % sizes[i]]);
    if (sizes[i] == 4) edge(p[0], p[2]), edge(p[1], p[3]);  // either diagonal
  }
  return {margin, on_edge};
}

// Distance in pixels from window point (cx, cy) to the nearest edge line of polygon id.
double edge_distance(const Camera& view, const std::vector<Vec3>& pts, int id, double cx, double cy) {
  double wx[3], wy[3], zc;
  for (int k = 0; k < 3; ++k) view.project(pts[4 * size_t(id) + k], wx[k], wy[k], zc);
  double best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const double ax = wx[k], ay = wy[k], bx = wx[(k + 1) % 3], by = wy[(k + 1) % 3];
    best = std::min(best, std::abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / std::hypot(bx - ax, by - ay));
  }
  return best;
}

}  // namespace

TEST(StencilBackends, DyadicScenesGiveIdenticalBuffersAndLayers) {
  auto gl = gl_or_skip();
  ASSERT_TRUE(gl);
  std::printf("GL: %s\n", gl->renderer().c_str());
  SoftwareBackend sw(RasterRule::gl);
  int64_t layered = 0;
  for (int size : {64, 128}) {
    for (uint64_t seed : {1u, 2u, 3u}) {
      std::vector<Vec3> pts;
      std::vector<int8_t> sizes;
      Camera view;
      dyadic_scene(size, seed, pts, sizes, view);
      const auto [margin, on_edge] = edge_margin(pts, sizes, size);
      ASSERT_GE(margin, 1.0 / 128);  // the construction's promise
      EXPECT_GT(on_edge, 100);
      gl->set_primitives(pts, sizes);
      sw.set_primitives(pts, sizes);
      const int32_t n = int32_t(sizes.size());
      const auto [gc, gg] = all_passes(*gl, n, view);
      const auto [sc, sg] = all_passes(sw, n, view);
      int64_t dc = 0, dg = 0, ds = 0, covered = 0, multi = 0;
      for (size_t p = 0; p < gc.colour.size(); ++p) {
        dc += gc.colour[p] != sc.colour[p];
        dg += gg.colour[p] != sg.colour[p];
        ds += gg.stencil[p] != sg.stencil[p];
        covered += sc.colour[p] != 0;
        multi += sg.stencil[p] > 1;
      }
      EXPECT_EQ(dc, 0) << size << " seed " << seed;
      EXPECT_EQ(dg, 0) << size << " seed " << seed;
      EXPECT_EQ(ds, 0) << size << " seed " << seed;
      EXPECT_GT(multi, covered / 8);  // plenty of overlap
      for (bool blocked : {false, true}) {
        const LayerResult a = layers(*gl, n, view, blocked), b = layers(sw, n, view, blocked);
        EXPECT_EQ(a.layer, b.layer) << size << " seed " << seed;
        EXPECT_EQ(a.footprint, b.footprint);
        EXPECT_EQ(a.complexity_passes, b.complexity_passes);
        EXPECT_EQ(b.unclassified_visible, 0);
        EXPECT_GE(b.layers, 3);
        layered += b.layers;
      }
    }
  }
  EXPECT_GT(layered, 0);
}

// Perspective views of closed surfaces: under the gl rule the buffers agree pixel for
// pixel; under the exact rule they differ only at pixel centres within the snapping
// distance of an edge.
TEST(StencilBackends, PerspectiveBuffersFollowTheGlRule) {
  auto gl = gl_or_skip();
  ASSERT_TRUE(gl);
  SoftwareBackend rule(RasterRule::gl), exact;
  int64_t pixels = 0, differing_rule = 0, differing_exact = 0, views = 0, same_layers = 0;
  double worst = 0;
  for (const auto& [name, subdiv] : {std::pair{"spheres", "1"}, std::pair{"sphere", "3"}}) {
    const Scene s = dataset(name, {{"subdiv", subdiv}});
    std::vector<Vec3> pts;
    std::vector<int8_t> sizes;
    polygons(s, pts, sizes);
    gl->set_primitives(pts, sizes);
    rule.set_primitives(pts, sizes);
    exact.set_primitives(pts, sizes);
    const int32_t n = int32_t(sizes.size());
    for (int size : {64, 128}) {
      for (int f = 0; f < 6; ++f) {
        const Camera view = orbit_view(s.bounds(), 6, f, ViewOptions{size, size});
        const auto [gc, gg] = all_passes(*gl, n, view);
        const auto [rc, rg] = all_passes(rule, n, view);
        const auto [sc, sg] = all_passes(exact, n, view);
        for (size_t p = 0; p < gc.colour.size(); ++p) {
          ++pixels;
          differing_rule += gc.colour[p] != rc.colour[p] || gg.colour[p] != rg.colour[p] ||
                            gg.stencil[p] != rg.stencil[p];
          if (gc.colour[p] == sc.colour[p]) continue;
          ++differing_exact;
          const double cx = double(p % size_t(size)) + 0.5, cy = double(p / size_t(size)) + 0.5;
          double d = 1e300;
          for (uint32_t c : {gc.colour[p], sc.colour[p]})
            if (c) d = std::min(d, edge_distance(view, pts, int(c - 1), cx, cy));
          worst = std::max(worst, d);
          EXPECT_LE(d, 1.0 / 256) << name << " " << size << " frame " << f << " pixel " << p;
        }
        ++views;
        same_layers += layers(*gl, n, view, false).layer == layers(rule, n, view, false).layer;
      }
    }
  }
  std::printf("perspective: %lld pixels; gl rule: %lld differing; exact rule: %lld differing candidate "
              "pixels (farthest %.5f px from an edge); identical layers under the gl rule in %lld of %lld views\n",
              (long long)pixels, (long long)differing_rule, (long long)differing_exact, worst,
              (long long)same_layers, (long long)views);
  EXPECT_EQ(differing_rule, 0);
  // Not every view: llvmpipe interpolates depth in floats from the origin, which on steep
  // triangles can reorder two depths tens of 24-bit steps apart that the rule (doubles)
  // orders the other way; the rule does not describe that (design-notes.md, issue 18).
  EXPECT_GT(same_layers, 0);
}
