#include "datasets/generators/volumes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "datasets/generators/splitmix.h"

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;

VoxelGrid grid_from_params(Params& p) {
  VoxelGrid g;
  g.dims = {p.get_int("nx", 64, 2, 512), p.get_int("ny", 64, 2, 512), p.get_int("nz", 64, 2, 512)};
  if (!p.dry_run()) g.values.resize(g.num_voxels());
  return g;
}

// Evaluates f at each voxel centre in normalised coordinates u in (0,1)^3.
void fill(VoxelGrid& g, const std::function<float(double, double, double)>& f) {
  const int nx = g.dims[0], ny = g.dims[1], nz = g.dims[2];
  size_t v = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        g.values[v++] = f((i + 0.5) / nx, (j + 0.5) / ny, (k + 0.5) / nz);
}

double sq(double a) { return a * a; }
}  // namespace

Scene make_block_volume(Params& p) {
  VoxelGrid g = grid_from_params(p);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  fill(g, [](double x, double y, double z) -> float {
    if (x < 0.08 || x > 0.92 || y < 0.2 || y > 0.8 || z < 0.1 || z > 0.9) return 0.0f;
    if (sq(x - 0.33) + sq(y - 0.5) < sq(0.12) || sq(x - 0.67) + sq(y - 0.5) < sq(0.12))
      return 0.0f;  // vertical bores
    if (sq(y - 0.5) + sq(z - 0.25) < sq(0.06)) return 0.0f;  // cross bore
    if (x > 0.42 && x < 0.58 && y > 0.3 && y < 0.7 && z > 0.45 && z < 0.8) return 0.0f;  // chamber
    // Denser skin near the outer faces, as in a cast part.
    const double skin = std::min({x - 0.08, 0.92 - x, y - 0.2, 0.8 - y, z - 0.1, 0.9 - z});
    return static_cast<float>(120.0 + 80.0 * std::exp(-skin / 0.03) + 20.0 * std::sin(9 * z));
  });
  return Scene::from_grid("block", std::move(g), p.to_json());
}

Scene make_shells_volume(Params& p) {
  VoxelGrid g = grid_from_params(p);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  fill(g, [](double x, double y, double z) -> float {
    const double r = std::sqrt(sq(x - 0.5) + sq(y - 0.5) + sq(z - 0.5));
    if (r < 0.14) return static_cast<float>(200.0 * (1.0 - r / 0.2));
    if (r > 0.24 && r < 0.28) return 120.0f;
    if (r > 0.38 && r < 0.42) return 60.0f;
    for (double cx : {0.1, 0.9})
      for (double cy : {0.1, 0.9})
        for (double cz : {0.1, 0.9})
          if (sq(x - cx) + sq(y - cy) + sq(z - cz) < sq(0.07)) return 160.0f;
    return 0.0f;
  });
  return Scene::from_grid("shells", std::move(g), p.to_json());
}

Scene make_sparse_volume(Params& p) {
  VoxelGrid g = grid_from_params(p);
  const int blobs = p.get_int("blobs", 40, 0, 10000);
  const int seed = p.get_int("seed", 1, 0, 1 << 30);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  const int nx = g.dims[0], ny = g.dims[1], nz = g.dims[2];
  const int n[3] = {nx, ny, nz};
  // Visits the voxels whose centres may lie within r of (cx, cy, cz) (normalised units).
  auto splat = [&](double cx, double cy, double cz, double r, auto&& value) {
    const double c[3] = {cx, cy, cz};
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, static_cast<int>(std::floor((c[a] - r) * n[a] - 0.5)));
      hi[a] = std::min(n[a] - 1, static_cast<int>(std::ceil((c[a] + r) * n[a] - 0.5)));
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          float& v = g.values[g.id(i, j, k)];
          v = std::max(v, static_cast<float>(value((i + 0.5) / nx - cx, (j + 0.5) / ny - cy,
                                                   (k + 0.5) / nz - cz)));
        }
  };
  SplitMix64 rng(static_cast<uint64_t>(seed));
  for (int b = 0; b < blobs; ++b) {
    const double x = rng.uniform(0.05, 0.95), y = rng.uniform(0.05, 0.95),
                 z = rng.uniform(0.05, 0.95), r = rng.uniform(0.02, 0.05),
                 peak = rng.uniform(50, 250);
    splat(x, y, z, r, [&](double dx, double dy, double dz) {
      const double d = std::sqrt(sq(dx) + sq(dy) + sq(dz));
      return d < r ? peak * (1.0 - d / r) + 1.0 : 0.0;
    });
  }
  // A thin helical wire (three turns around the vertical axis), one disc per z slice, thick
  // enough that every slice holds a voxel centre (so the volume is never empty).
  const double wire = std::max(0.015, 0.75 * std::max(1.0 / nx, 1.0 / ny));
  for (int k = 0; k < nz; ++k) {
    const double z = (k + 0.5) / nz, a = 2 * kPi * 3 * z;
    splat(0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a), z, wire,
          [&](double dx, double dy, double dz) {
            return dz == 0.0 && sq(dx) + sq(dy) < sq(wire) ? 90.0 : 0.0;
          });
  }
  return Scene::from_grid("sparse", std::move(g), p.to_json());
}

}  // namespace vob
