#include "datasets/generators/touching_blocks.h"

#include <cmath>

#include "datasets/generators/kuhn_block.h"

namespace vob {

namespace {

// Scalars: a gentle gradient per block plus a per-block offset, so that images tell the
// blocks apart.
void fill_scalars(CellMesh& m, int32_t first, double offset, double size) {
  m.scalars.resize(m.points.size());
  for (size_t i = static_cast<size_t>(first); i < m.points.size(); ++i) {
    const Vec3 p = m.points[i];
    m.scalars[i] = offset + 0.3 * (p.x + 0.5 * p.y + 0.25 * p.z) / (1.75 * size);
  }
}

int32_t tet_block(CellMesh& m, int nx, int ny, int nz, Vec3 origin, Vec3 spacing, double scalar, double size) {
  const int32_t first = append_kuhn_block(m, BlockSpec{nx, ny, nz, origin, spacing});
  fill_scalars(m, first, scalar, size);
  return first;
}

// A block of nx x ny x nz hexahedra in VTK vertex order (bottom loop counter-clockwise
// seen from above, then the top loop), positively oriented.
int32_t hex_block(CellMesh& m, int nx, int ny, int nz, Vec3 origin, Vec3 spacing, double scalar, double size) {
  const auto first = static_cast<int32_t>(m.points.size());
  const int sx = nx + 1, sy = ny + 1;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.points.push_back({origin.x + i * spacing.x, origin.y + j * spacing.y, origin.z + k * spacing.z});
  auto id = [&](int i, int j, int k) { return first + static_cast<int32_t>(i + sx * (j + sy * k)); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int32_t ids[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        m.add_cell(CellType::Hexahedron, ids);
      }
  fill_scalars(m, first, scalar, size);
  return first;
}

using BlockFn = int32_t (*)(CellMesh&, int, int, int, Vec3, Vec3, double, double);

// Every scene stands on the same lower block: n x n x h unit cells from the origin.
struct Base {
  int n, h;  // cells per side, layers (h = n/2, at least 1)
  CellMesh m;
  Base(Params& p, BlockFn block = tet_block) : n(p.get_int("n", 6, 1, 40)), h(std::max(1, n / 2)) {
    block(m, n, n, h, {0, 0, 0}, {1, 1, 1}, 0.2, n);
  }
  // An upper block like the lower one, its corner at (x, y, h); returns its first point.
  int32_t upper(double x, double y, BlockFn block = tet_block) {
    return block(m, n, n, h, {x, y, double(h)}, {1, 1, 1}, 0.5, n);
  }
};

Scene finish(const char* name, Base& b, Params& p) {
  return Scene::from_mesh(name, std::move(b.m), p.to_json());
}

}  // namespace

Scene make_touching_conforming(Params& p) {
  Base b(p);
  b.upper(0, 0);
  return finish("touching-conforming", b, p);
}

Scene make_touching_shifted(Params& p) {
  Base b(p);
  b.upper(0.5, 0.5);
  return finish("touching-shifted", b, p);
}

Scene make_touching_rotated(Params& p) {
  Base b(p);
  const double angle = p.get_double("angle", 11, -180, 180);
  const int32_t first = b.upper(0, 0);
  // A rotation about a vertical axis keeps every z, so the interface stays exactly planar
  // and the cells keep their orientation.
  const double a = angle * std::acos(-1.0) / 180, c = std::cos(a), s = std::sin(a), mid = 0.5 * b.n;
  for (size_t i = static_cast<size_t>(first); i < b.m.points.size(); ++i) {
    Vec3& q = b.m.points[i];
    const double x = q.x - mid, y = q.y - mid;
    q.x = mid + c * x - s * y;
    q.y = mid + s * x + c * y;
  }
  return finish("touching-rotated", b, p);
}

Scene make_touching_overhang(Params& p) {
  Base b(p);
  // n x n half-unit cells: side n/2, from x = 3n/4 to 5n/4 (beyond the lower block's n).
  tet_block(b.m, b.n, b.n, b.h, {0.75 * b.n, 0.25 * b.n, double(b.h)}, {0.5, 0.5, 0.5}, 0.5, b.n);
  return finish("touching-overhang", b, p);
}

Scene make_touching_edge(Params& p) {
  Base b(p);
  // A: [0,n] x [0,n] x [0,h]; B: [n, 1.5n] x [0,n] x [0,h] at half-unit cells;
  // C: [0,n] x [0.5, n+0.5] x [h, 2h]. A|B and B|C are separated by x = n, A|C by z = h.
  tet_block(b.m, b.n, 2 * b.n, 2 * b.h, {double(b.n), 0, 0}, {0.5, 0.5, 0.5}, 0.4, b.n);
  tet_block(b.m, b.n, b.n, b.h, {0, 0.5, double(b.h)}, {1, 1, 1}, 0.6, b.n);
  return finish("touching-edge", b, p);
}

Scene make_touching_hex(Params& p) {
  Base b(p, hex_block);
  b.upper(0.5, 0.5, hex_block);
  return finish("touching-hex", b, p);
}

}  // namespace vob
