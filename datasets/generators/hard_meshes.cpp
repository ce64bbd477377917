#include "datasets/generators/hard_meshes.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "datasets/generators/gap.h"
#include "datasets/generators/helix.h"
#include "datasets/generators/prism_split.h"
#include "datasets/generators/splitmix.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
double signed_volume(const CellMesh& m, const int32_t* v) {
  const Vec3 a = m.points[v[0]];
  return dot(cross(m.points[v[1]] - a, m.points[v[2]] - a), m.points[v[3]] - a);
}
double cross2(Vec3 a, Vec3 b, Vec3 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }
}  // namespace

Scene make_offset(Params& p) {
  const std::string shape = p.get_choice("shape", "helix", {"helix", "gap"});
  const double off = p.get_double("offset", 1e7, -1e9, 1e9);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m = shape == "helix" ? make_helix_mesh({2000, 2, {off, off, off}})
                                : make_gap_mesh({6, 6, 12, 2, {off, off, off}});
  return Scene::from_mesh("offset", std::move(m), p.to_json());
}

Scene make_slivers(Params& p) {
  const int n = p.get_int("n", 8, 1, 200);
  const double eps = p.get_double("flatness", 1e-6, 1e-12, 0.25);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m;
  const int s = n + 1;
  // Layers: 0 bottom (z=-1), 1 middle (z=+-eps), 2 top (z=1).
  auto id = [&](int layer, int i, int j) { return static_cast<int32_t>(layer * s * s + j * s + i); };
  for (int layer = 0; layer < 3; ++layer)
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i) {
        const double z = layer == 0 ? -1.0 : layer == 2 ? 1.0 : ((i + j) % 2 == 0 ? eps : -eps);
        m.points.push_back({double(i), double(j), z});
        m.scalars.push_back(0.3 + 0.5 * layer / 2.0 + 0.2 * ((i + j) % 2));
      }
  auto add_prism = [&](int lo, int hi, std::array<std::array<int, 2>, 3> tri) {
    // Bottom triangle clockwise seen from above (VTK wedge orientation).
    const Vec3 a = m.points[id(lo, tri[0][0], tri[0][1])], b = m.points[id(lo, tri[1][0], tri[1][1])],
               c = m.points[id(lo, tri[2][0], tri[2][1])];
    if (cross2(a, b, c) > 0) std::swap(tri[1], tri[2]);
    int32_t ids[6];
    for (int q = 0; q < 3; ++q) {
      ids[q] = id(lo, tri[q][0], tri[q][1]);
      ids[q + 3] = id(hi, tri[q][0], tri[q][1]);
    }
    int32_t tets[3][4];
    split_prism(ids, tets);
    for (const auto& t : tets) m.add_cell(CellType::Tetra, t);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::array<int, 2> a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
      // The sliver's upper faces hold its high diagonal (a-c when a is high), the lower
      // faces its low diagonal; prisms stand on them up to z=1 and down to z=-1.
      const bool even = (i + j) % 2 == 0;
      const auto up1 = even ? std::array{a, b, c} : std::array{a, b, d};
      const auto up2 = even ? std::array{a, c, d} : std::array{b, c, d};
      const auto dn1 = even ? std::array{a, b, d} : std::array{a, b, c};
      const auto dn2 = even ? std::array{b, c, d} : std::array{a, c, d};
      add_prism(1, 2, up1);
      add_prism(1, 2, up2);
      add_prism(0, 1, dn1);
      add_prism(0, 1, dn2);
      int32_t t[4] = {id(1, i, j), id(1, i + 1, j), id(1, i + 1, j + 1), id(1, i, j + 1)};
      if (signed_volume(m, t) < 0) std::swap(t[1], t[2]);
      m.add_cell(CellType::Tetra, t);
    }
  return Scene::from_mesh("slivers", std::move(m), p.to_json());
}

Scene make_tiny(Params& p) {
  const int count = p.get_int("count", 2000, 1, 2000000);
  const double size = p.get_double("size", 1e-3, 1e-9, 0.05);
  const int seed = p.get_int("seed", 1, 0, 1 << 30);
  const int g = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(count)) - 1e-9));
  // A tetrahedron reaches at most ~0.87*size*1.2 from its centre; centres keep a margin
  // of a quarter grid cell, so neighbours cannot touch.
  if (size * 1.1 > 0.25 / g)
    throw InputError("tiny", "parameter size", std::to_string(size) + " is too large for " +
                                                   std::to_string(count) + " cells (max " +
                                                   std::to_string(0.25 / g / 1.1) + ")");
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  SplitMix64 rng(static_cast<uint64_t>(seed));
  std::vector<int32_t> slots(static_cast<size_t>(g) * g * g);
  std::iota(slots.begin(), slots.end(), 0);
  for (size_t i = slots.size() - 1; i > 0; --i)  // Fisher-Yates with our own generator
    std::swap(slots[i], slots[rng.next() % (i + 1)]);
  slots.resize(count);
  std::sort(slots.begin(), slots.end());
  CellMesh m;
  m.points.reserve(4 * size_t(count));
  m.scalars.reserve(4 * size_t(count));
  const Vec3 reg[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};  // regular tet
  for (int32_t slot : slots) {
    const int i = slot % g, j = (slot / g) % g, k = slot / (g * g);
    const Vec3 c{(i + rng.uniform(0.25, 0.75)) / g, (j + rng.uniform(0.25, 0.75)) / g,
                 (k + rng.uniform(0.25, 0.75)) / g};
    const double s = rng.uniform(0.3, 1.0);
    int32_t t[4];
    for (int q = 0; q < 4; ++q) {
      const Vec3 jitter{rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)};
      t[q] = static_cast<int32_t>(m.points.size());
      m.points.push_back(c + (reg[q] * 0.35355 + jitter) * size);  // edge ~ size
      m.scalars.push_back(s);
    }
    if (signed_volume(m, t) < 0) std::swap(t[1], t[2]);
    m.add_cell(CellType::Tetra, t);
  }
  return Scene::from_mesh("tiny", std::move(m), p.to_json());
}

}  // namespace vob
