// The centroid orderer's per-frame keys, a run of cells at a time, from centroids stored as
// three float arrays (x, y, z) relative to an origin near the mesh (as VTK keeps its cell
// centres in a vtkFloatArray, but relative: rounded to 6e-8 of the mesh's extent, not of
// its distance from the world origin): the sortable bits of float(-key), key = view depth
// dot(c - eye, f) or eye distance length(c - eye) with c the stored centroid widened to
// double and the eye taken relative to the same origin, in the same double operations in
// the same order as Vec3's dot and length, so every build and CPU path gives the same bits.
// Floats halve the bytes the key pass streams: 12 a cell, not 24.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "harness/geometry/vec3.h"
#include "harness/sort/radix_sort.h"

namespace vob {

struct CentroidArrays {
  const float *x, *y, *z;
};

// Cell i's key bits, the one formula of both kernels and of the threaded key pass.
template <bool kByView>
inline __attribute__((always_inline)) uint32_t centroid_key(CentroidArrays c, Vec3 eye, Vec3 f, size_t i) {
  const double dx = double(c.x[i]) - eye.x, dy = double(c.y[i]) - eye.y, dz = double(c.z[i]) - eye.z;
  const double d = kByView ? dx * f.x + dy * f.y + dz * f.z : std::sqrt(dx * dx + dy * dy + dz * dz);
  return float_sort_key(static_cast<float>(-d));
}

// k[i - i0] = the key bits of cell i, for i in [i0, i1).
using CentroidKeyRun = void (*)(CentroidArrays c, Vec3 eye, Vec3 f, size_t i0, size_t i1, uint32_t* k);

// The run kernel for the view-depth or the eye-distance key: AVX2 (4 doubles a step; no FMA,
// which would round differently) when the CPU has it, else the baseline build's SSE2 loop.
CentroidKeyRun centroid_key_run(bool by_view);
CentroidKeyRun centroid_key_run_baseline(bool by_view);  // for tests: the non-AVX2 path

}  // namespace vob
