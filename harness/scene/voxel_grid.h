// VoxelGrid: a regular volume. Voxel (i,j,k) has centre origin + (i,j,k)*spacing and id
// i + nx*(j + ny*k). Voxels whose value exceeds `threshold` are significant: only they are
// ordered, splatted and checked.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/geometry/vec3.h"

namespace vob {

struct VoxelRun {  // significant voxels [i0, i0+len) on row (j,k)
  int32_t j, k, i0, len;
};

struct VoxelGrid {
  std::array<int32_t, 3> dims{0, 0, 0};
  Vec3 spacing{1, 1, 1};
  Vec3 origin{0, 0, 0};
  std::vector<float> values;  // nx*ny*nz
  float threshold = 0.0f;

  size_t num_voxels() const { return static_cast<size_t>(dims[0]) * dims[1] * dims[2]; }
  int64_t id(int i, int j, int k) const { return i + int64_t(dims[0]) * (j + int64_t(dims[1]) * k); }
  Vec3 centre(int i, int j, int k) const {
    return {origin.x + i * spacing.x, origin.y + j * spacing.y, origin.z + k * spacing.z};
  }
  Vec3 centre_of(int64_t id) const;
  bool significant(int64_t id) const { return values[id] > threshold; }
  Aabb bounds() const;  // of the voxel boxes (centres +- spacing/2)
  size_t bytes() const { return values.capacity() * sizeof(float); }
};

// Significant voxel ids in id order, and their runs along x.
std::vector<int32_t> significant_voxels(const VoxelGrid& g);
std::vector<VoxelRun> significant_runs(const VoxelGrid& g);

// Dims positive, voxel count below 2^31, spacing positive and finite, values finite.
void validate_voxel_grid(const VoxelGrid& g, const std::string& source);

}  // namespace vob
