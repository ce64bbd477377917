#include "harness/scene/voxel_grid.h"

#include <algorithm>
#include <cmath>

#include "harness/scene/coordinates.h"
#include "harness/scene/input_error.h"

namespace vob {

Vec3 VoxelGrid::centre_of(int64_t id) const {
  const int64_t nx = dims[0], ny = dims[1];
  const int i = static_cast<int>(id % nx), j = static_cast<int>((id / nx) % ny),
            k = static_cast<int>(id / (nx * ny));
  return centre(i, j, k);
}

Aabb VoxelGrid::bounds() const {
  Aabb b;
  if (num_voxels() == 0) return b;
  b.add(origin - spacing * 0.5);
  b.add(centre(dims[0] - 1, dims[1] - 1, dims[2] - 1) + spacing * 0.5);
  return b;
}

std::vector<int32_t> significant_voxels(const VoxelGrid& g) {
  std::vector<int32_t> ids;
  for (size_t v = 0; v < g.num_voxels(); ++v)
    if (g.values[v] > g.threshold) ids.push_back(static_cast<int32_t>(v));
  return ids;
}

std::vector<VoxelRun> significant_runs(const VoxelGrid& g) {
  std::vector<VoxelRun> runs;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j) {
      int i = 0;
      while (i < g.dims[0]) {
        while (i < g.dims[0] && !g.significant(g.id(i, j, k))) ++i;
        const int start = i;
        while (i < g.dims[0] && g.significant(g.id(i, j, k))) ++i;
        if (i > start) runs.push_back({j, k, start, i - start});
      }
    }
  return runs;
}

void validate_voxel_grid(const VoxelGrid& g, const std::string& source) {
  for (int a = 0; a < 3; ++a)
    if (g.dims[a] <= 0)
      throw InputError(source, "dims", "dimension " + std::to_string(a) + " is " +
                                           std::to_string(g.dims[a]) + ", must be positive");
  if (static_cast<double>(g.dims[0]) * g.dims[1] * g.dims[2] >= 2147483647.0)
    throw InputError(source, "dims", "more than 2^31 voxels");
  if (!is_finite(g.spacing) || g.spacing.x <= 0 || g.spacing.y <= 0 || g.spacing.z <= 0)
    throw InputError(source, "spacing", "must be positive and finite");
  if (!is_finite(g.origin)) throw InputError(source, "origin", "is not finite");
  if (!std::isfinite(g.threshold)) throw InputError(source, "threshold", "is not finite");
  const Aabb box = g.bounds();
  for (const Vec3 corner : {box.lo, box.hi})
    if (!is_finite(corner) || std::max({std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)}) >
                                  kMaxAbsCoordinate)
      throw InputError(source, "origin/spacing", "the grid reaches beyond +-1e150 (squared distances would overflow)");
  check_extent(box, source);
  // Each step must be resolvable too: a spacing that underflows when squared, or that is
  // lost against the coordinates, leaves voxels that no depth can separate.
  const double scale = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                                 std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
  for (const double step : {g.spacing.x, g.spacing.y, g.spacing.z})
    if (step < kMinExtent || step < kMinRelativeExtent * scale)
      throw InputError(source, "spacing", "a step of " + short_number(step) +
                                              " is degenerate at coordinates of " + short_number(scale));
  if (g.values.size() != g.num_voxels())
    throw InputError(source, "values", "expected " + std::to_string(g.num_voxels()) +
                                           " values, got " + std::to_string(g.values.size()));
  for (size_t v = 0; v < g.values.size(); ++v)
    if (!std::isfinite(g.values[v]))
      throw InputError(source, "voxel " + std::to_string(v), "value is not finite");
}

}  // namespace vob
