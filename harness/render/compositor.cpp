// Emission-absorption compositing of the collector's fragments, one band of rows at a time.
#include "harness/render/compositor.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "harness/raster/fragments.h"
#include "harness/raster/splat.h"

namespace vob {

namespace {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

// The fixed transfer function: a two-colour ramp, green (low) to pink (high).
Rgb ramp(double s) {
  const Rgb lo{0.15, 0.80, 0.30}, hi{1.00, 0.35, 0.70};
  return {lo.r + s * (hi.r - lo.r), lo.g + s * (hi.g - lo.g), lo.b + s * (hi.b - lo.b)};
}

void over(Rgb& c, const Rgb& src, double alpha) {
  c.r = src.r * alpha + c.r * (1 - alpha);
  c.g = src.g * alpha + c.g * (1 - alpha);
  c.b = src.b * alpha + c.b * (1 - alpha);
}

constexpr double kTriangleAlpha = 0.3;
// Cells: extinction tau0 * (0.25 + 0.75 s) with tau0 = kOpticalScale / bounding radius. A
// mean chord of the bounding sphere is 4/3 radii and s averages about 0.5, so a typical ray
// through the mesh has an optical depth of about 2 (range roughly 1-3).
constexpr double kOpticalScale = 2.4;

// Per-primitive shading data and the colour of one fragment.
class Shader {
 public:
  Shader(const Scene& scene, const FragmentCollector& fc) : scene_(scene), fc_(fc) {
    const SceneKind k = scene.kind();
    if (k == SceneKind::Cells) {
      const CellMesh& m = scene.mesh();
      double lo = 0, hi = 0;
      if (!m.scalars.empty()) {
        lo = *std::min_element(m.scalars.begin(), m.scalars.end());
        hi = *std::max_element(m.scalars.begin(), m.scalars.end());
      }
      level_.resize(m.num_cells());
      tbb::parallel_for(size_t(0), m.num_cells(), [&](size_t c) {
        level_[c] = hi > lo ? float((m.cell_scalar(c) - lo) / (hi - lo)) : 0.5f;
      });
      tau0_ = kOpticalScale / std::max(scene.bounds().radius(), 1e-300);
    } else if (k == SceneKind::Triangles) {
      const TriangleSoup& s = scene.soup();
      normal_.resize(s.num_triangles());
      for (size_t t = 0; t < s.num_triangles(); ++t) {
        const auto& v = s.tris[t];
        normal_[t] = normalize(cross(s.points[v[1]] - s.points[v[0]], s.points[v[2]] - s.points[v[0]]));
      }
    } else {
      const VoxelGrid& g = scene.grid();
      vlo_ = g.threshold;
      vhi_ = vlo_;
      for (float v : g.values) vhi_ = std::max(vhi_, double(v));
    }
  }

  void composite(Rgb& c, const Fragment& f, int sx, int sy) const {
    switch (scene_.kind()) {
      case SceneKind::Cells: {
        const double s = level_[f.prim];
        const double a = 1 - std::exp(-tau0_ * (0.25 + 0.75 * s) * (f.t_out - f.t_in));
        over(c, ramp(s), a);
        break;
      }
      case SceneKind::Triangles: {
        // Two-sided headlight shading.
        const double shade = 0.2 + 0.8 * std::fabs(dot(normal_[f.prim], fc_.frame().ray(sx, sy).dir));
        over(c, {0.55 * shade, 0.70 * shade, 0.95 * shade}, kTriangleAlpha);
        break;
      }
      case SceneKind::Voxels: {
        const VoxelGrid& g = scene_.grid();
        const double v = vhi_ > vlo_ ? (g.values[f.prim] - vlo_) / (vhi_ - vlo_) : 1.0;
        Splat sp;
        make_splat(fc_.frame(), g.centre_of(f.prim), g.spacing, fc_.splat_radius_px(), sp);
        const double dx = sx + 0.5 - sp.cx, dy = sy + 0.5 - sp.cy;
        const double q = (dx * dx + dy * dy) / (sp.radius * sp.radius);
        over(c, ramp(v), (0.1 + 0.5 * v) * std::exp(-2.0 * q));  // Gaussian footprint
        break;
      }
    }
  }

 private:
  const Scene& scene_;
  const FragmentCollector& fc_;
  std::vector<float> level_;
  std::vector<Vec3> normal_;
  double tau0_ = 0, vlo_ = 0, vhi_ = 1;
};

Image render(const Scene& scene, const Camera& view, const std::vector<int32_t>& order,
             const RenderOptions& opt, bool exact) {
  CollectOptions co;
  co.splat_radius_px = opt.splat_radius_px;
  const FragmentCollector fc(scene, view, order, co);
  const Shader shader(scene, fc);
  Image img;
  img.width = view.width;
  img.height = view.height;
  img.rgb.assign(size_t(img.width) * img.height * 3, 0.0f);
  struct Scratch {
    FragmentLists lists;
    std::vector<Fragment> sorted;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(0, fc.num_bands(), [&](int b) {
    Scratch& s = scratch.local();
    fc.collect_band(b, s.lists);
    for (int y = s.lists.row0; y < s.lists.row1; ++y)
      for (int x = 0; x < img.width; ++x) {
        const auto frags = s.lists.at(x, y);
        std::span<const Fragment> seq = frags;
        if (exact) {
          // Far to near; equal depths by primitive id, independent of any drawing order.
          s.sorted.assign(frags.begin(), frags.end());
          std::sort(s.sorted.begin(), s.sorted.end(), [](const Fragment& a, const Fragment& b) {
            return a.mid() != b.mid() ? a.mid() > b.mid() : a.prim > b.prim;
          });
          seq = s.sorted;
        }
        Rgb c;
        for (const Fragment& f : seq) shader.composite(c, f, x, y);
        float* p = &img.rgb[(size_t(y) * img.width + x) * 3];
        p[0] = float(std::clamp(c.r, 0.0, 1.0));
        p[1] = float(std::clamp(c.g, 0.0, 1.0));
        p[2] = float(std::clamp(c.b, 0.0, 1.0));
      }
  });
  return img;
}

}  // namespace

Image render_in_order(const Scene& scene, const Camera& view, const std::vector<int32_t>& order,
                      const RenderOptions& opt) {
  return render(scene, view, order, opt, false);
}

Image render_exact(const Scene& scene, const Camera& view, const RenderOptions& opt) {
  return render(scene, view, all_primitives(scene), opt, true);
}

}  // namespace vob
