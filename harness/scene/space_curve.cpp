#include "harness/scene/space_curve.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace vob {

namespace {
// The low 21 bits of x spread to every third bit.
uint64_t spread3(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

uint64_t quantize(double v, double lo, double hi) {
  constexpr double kMax = double((1u << 21) - 1);
  if (!(hi > lo)) return 0;
  const double q = (v - lo) / (hi - lo) * kMax;
  return static_cast<uint64_t>(std::clamp(q, 0.0, kMax));
}

// Stable LSD radix sort of ids by 64-bit keys, 11-bit digits; a digit every key shares is
// skipped (a 1M-cell mesh's codes differ in far fewer than 63 bits).
void radix_sort_ids(std::vector<uint64_t>& keys, std::vector<int32_t>& ids) {
  constexpr int kBits = 11, kBuckets = 1 << kBits;
  const size_t n = keys.size();
  std::vector<uint64_t> k2(n);
  std::vector<int32_t> i2(n);
  std::vector<size_t> count(kBuckets);
  for (int shift = 0; shift < 64; shift += kBits) {
    std::fill(count.begin(), count.end(), 0);
    for (uint64_t k : keys) ++count[(k >> shift) & (kBuckets - 1)];
    if (n == 0 || count[(keys[0] >> shift) & (kBuckets - 1)] == n) continue;
    size_t sum = 0;
    for (size_t& c : count) sum += std::exchange(c, sum);
    for (size_t i = 0; i < n; ++i) {
      const size_t slot = count[(keys[i] >> shift) & (kBuckets - 1)]++;
      k2[slot] = keys[i];
      i2[slot] = ids[i];
    }
    keys.swap(k2);
    ids.swap(i2);
  }
}

void check_permutation(const std::vector<int32_t>& order, size_t n, const char* what) {
  if (order.size() != n) throw std::invalid_argument(std::string(what) + ": wrong size");
  std::vector<uint8_t> seen(n, 0);
  for (int32_t i : order) {
    if (i < 0 || static_cast<size_t>(i) >= n || seen[i])
      throw std::invalid_argument(std::string(what) + ": not a permutation");
    seen[i] = 1;
  }
}

// Cells of `mesh` in `cell_order`, their vertex ids mapped through `new_point`.
void copy_cells(const CellMesh& mesh, const std::vector<int32_t>& cell_order,
                const std::vector<int32_t>& new_point, CellMesh& out) {
  const size_t nc = mesh.num_cells();
  out.types.resize(nc);
  out.offsets.assign(nc + 1, 0);
  out.conn.resize(mesh.conn.size());
  int32_t at = 0;
  for (size_t c = 0; c < nc; ++c) {
    const int32_t old = cell_order[c];
    out.types[c] = mesh.types[old];
    const int32_t* p = mesh.cell_points(old);
    for (int k = 0, n = mesh.cell_size(old); k < n; ++k) out.conn[at++] = new_point[p[k]];
    out.offsets[c + 1] = at;
  }
}

void copy_points(const CellMesh& mesh, const std::vector<int32_t>& point_order, CellMesh& out) {
  const size_t np = point_order.size();
  out.points.resize(np);
  out.scalars.resize(mesh.scalars.empty() ? 0 : np);
  for (size_t p = 0; p < np; ++p) {
    out.points[p] = mesh.points[point_order[p]];
    if (!mesh.scalars.empty()) out.scalars[p] = mesh.scalars[point_order[p]];
  }
}
}  // namespace

size_t RenumberedMesh::bytes() const {
  return mesh.bytes() + (input_cell.capacity() + input_point.capacity()) * sizeof(int32_t);
}

uint64_t morton_code(Vec3 p, const Aabb& box) {
  return spread3(quantize(p.x, box.lo.x, box.hi.x)) |
         spread3(quantize(p.y, box.lo.y, box.hi.y)) << 1 |
         spread3(quantize(p.z, box.lo.z, box.hi.z)) << 2;
}

uint64_t hilbert_code(Vec3 p, const Aabb& box) {
  // Skilling's transform (AIP Conf. Proc. 707, 2004): axes to the "transposed" Hilbert
  // index, whose bits interleaved (x most significant) are the index.
  uint64_t x[3] = {quantize(p.x, box.lo.x, box.hi.x), quantize(p.y, box.lo.y, box.hi.y),
                   quantize(p.z, box.lo.z, box.hi.z)};
  // Each step's choice by masks, not jumps: the bits of a centroid are coin tosses, and the
  // jumps mispredicted (hilbert_code was 4% of loading and ordering a 1.3M-cell gmsh mesh).
  constexpr uint64_t kTop = uint64_t(1) << 20;
  for (uint64_t q = kTop; q > 1; q >>= 1) {
    const uint64_t mask = q - 1;
    for (int i = 0; i < 3; ++i) {
      const uint64_t set = uint64_t(0) - ((x[i] & q) != 0);  // all ones when the bit is set
      const uint64_t t = (x[0] ^ x[i]) & mask & ~set;         // exchange (when clear)
      x[0] ^= (mask & set) | t;                               // invert (when set)
      x[i] ^= t;
    }
  }
  x[1] ^= x[0];
  x[2] ^= x[1];
  uint64_t t = 0;
  for (uint64_t q = kTop; q > 1; q >>= 1) t ^= (q - 1) & (uint64_t(0) - ((x[2] & q) != 0));
  for (uint64_t& v : x) v ^= t;
  return spread3(x[0]) << 2 | spread3(x[1]) << 1 | spread3(x[2]);
}

std::vector<int32_t> curve_cell_order(const CellMesh& mesh, Curve curve) {
  const size_t nc = mesh.num_cells();
  const Aabb box = mesh.bounds();
  std::vector<uint64_t> keys(nc);
  std::vector<int32_t> ids(nc);
  for (size_t c = 0; c < nc; ++c) {
    const Vec3 centroid = mesh.cell_centroid(c);
    keys[c] = curve == Curve::Hilbert ? hilbert_code(centroid, box) : morton_code(centroid, box);
    ids[c] = static_cast<int32_t>(c);
  }
  radix_sort_ids(keys, ids);
  return ids;
}

RenumberedMesh permute_cells(const CellMesh& mesh, const std::vector<int32_t>& cell_order) {
  check_permutation(cell_order, mesh.num_cells(), "permute_cells");
  RenumberedMesh r;
  const size_t np = mesh.num_points();
  std::vector<int32_t> new_point(np, -1);
  r.input_point.reserve(np);
  for (int32_t old : cell_order) {
    const int32_t* p = mesh.cell_points(old);
    for (int k = 0, n = mesh.cell_size(old); k < n; ++k)
      if (new_point[p[k]] < 0) {
        new_point[p[k]] = static_cast<int32_t>(r.input_point.size());
        r.input_point.push_back(p[k]);
      }
  }
  for (size_t p = 0; p < np; ++p)
    if (new_point[p] < 0) {
      new_point[p] = static_cast<int32_t>(r.input_point.size());
      r.input_point.push_back(static_cast<int32_t>(p));
    }
  copy_points(mesh, r.input_point, r.mesh);
  copy_cells(mesh, cell_order, new_point, r.mesh);
  r.input_cell = cell_order;
  return r;
}

CellMesh permute_mesh(const CellMesh& mesh, const std::vector<int32_t>& cell_order,
                      const std::vector<int32_t>& point_order) {
  check_permutation(cell_order, mesh.num_cells(), "permute_mesh cells");
  check_permutation(point_order, mesh.num_points(), "permute_mesh points");
  std::vector<int32_t> new_point(point_order.size());
  for (size_t p = 0; p < point_order.size(); ++p) new_point[point_order[p]] = static_cast<int32_t>(p);
  CellMesh out;
  copy_points(mesh, point_order, out);
  copy_cells(mesh, cell_order, new_point, out);
  return out;
}

double far_reuse_fraction(const CellMesh& mesh, const std::vector<int32_t>& cell_order, int32_t near) {
  const size_t nc = mesh.num_cells();
  if (!cell_order.empty() && cell_order.size() != nc)
    throw std::invalid_argument("far_reuse_fraction: wrong size");
  std::vector<int32_t> last(mesh.num_points(), -1);  // new id of the last cell using a point
  int64_t reuses = 0, far = 0;
  for (size_t c = 0; c < nc; ++c) {
    const int32_t old = cell_order.empty() ? static_cast<int32_t>(c) : cell_order[c];
    const int32_t* p = mesh.cell_points(old);
    for (int k = 0, n = mesh.cell_size(old); k < n; ++k) {
      const int32_t prev = std::exchange(last[p[k]], static_cast<int32_t>(c));
      if (prev < 0) continue;
      ++reuses;
      far += static_cast<int32_t>(c) - prev > near;
    }
  }
  return reuses ? static_cast<double>(far) / static_cast<double>(reuses) : 0.0;
}

RenumberedMesh renumber_along_curve(const CellMesh& mesh, Curve curve) {
  return permute_cells(mesh, curve_cell_order(mesh, curve));
}

}  // namespace vob
