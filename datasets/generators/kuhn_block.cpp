#include "datasets/generators/kuhn_block.h"

#include <array>

namespace vob {

namespace {
// The six tetrahedra of the unit cube: for each permutation (a,b,c) of the axes, the path
// 000 -> +e_a -> +e_b -> 111. Corners are coded as bit x | y<<1 | z<<2. Odd permutations
// have negative volume, so their middle two vertices are swapped.
struct KuhnTable {
  std::array<std::array<int, 4>, 6> tet;
  KuhnTable() {
    const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    for (int p = 0; p < 6; ++p) {
      const int v1 = 1 << perms[p][0], v2 = v1 | (1 << perms[p][1]);
      tet[p] = p < 3 ? std::array<int, 4>{0, v1, v2, 7} : std::array<int, 4>{0, v2, v1, 7};
    }
  }
};
}  // namespace

int32_t append_kuhn_block(CellMesh& m, const BlockSpec& b) {
  static const KuhnTable kuhn;
  const auto first = static_cast<int32_t>(m.points.size());
  const int64_t sx = b.nx + 1, sy = b.ny + 1, sz = b.nz + 1;
  m.points.reserve(m.points.size() + sx * sy * sz);
  for (int k = 0; k < sz; ++k)
    for (int j = 0; j < sy; ++j)
      for (int i = 0; i < sx; ++i)
        m.points.push_back({b.origin.x + i * b.spacing.x, b.origin.y + j * b.spacing.y,
                            b.origin.z + k * b.spacing.z});
  const int64_t cells = int64_t(6) * b.nx * b.ny * b.nz;
  m.types.reserve(m.types.size() + cells);
  m.offsets.reserve(m.offsets.size() + cells);
  m.conn.reserve(m.conn.size() + 4 * cells);
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        int32_t corner[8];
        for (int c = 0; c < 8; ++c)
          corner[c] = first + static_cast<int32_t>((i + (c & 1)) +
                                                   sx * ((j + ((c >> 1) & 1)) + sy * (k + (c >> 2))));
        for (const auto& t : kuhn.tet) {
          const int32_t ids[4] = {corner[t[0]], corner[t[1]], corner[t[2]], corner[t[3]]};
          m.add_cell(CellType::Tetra, ids);
        }
      }
  return first;
}

}  // namespace vob
