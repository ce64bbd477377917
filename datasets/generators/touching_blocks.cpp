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

struct Base {
  int n, h;  // cells per side, layers (h = n/2, at least 1)
};
Base base(Params& p) {
  const int n = p.get_int("n", 6, 1, 40);
  return {n, std::max(1, n / 2)};
}

Scene finish(const char* name, CellMesh m, Params& p) {
  return Scene::from_mesh(name, std::move(m), p.to_json());
}

}  // namespace

Scene make_touching_conforming(Params& p) {
  const Base b = base(p);
  CellMesh m;
  tet_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  tet_block(m, b.n, b.n, b.h, {0, 0, double(b.h)}, {1, 1, 1}, 0.5, b.n);
  return finish("touching-conforming", std::move(m), p);
}

Scene make_touching_shifted(Params& p) {
  const Base b = base(p);
  CellMesh m;
  tet_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  tet_block(m, b.n, b.n, b.h, {0.5, 0.5, double(b.h)}, {1, 1, 1}, 0.5, b.n);
  return finish("touching-shifted", std::move(m), p);
}

Scene make_touching_rotated(Params& p) {
  const Base b = base(p);
  const double angle = p.get_double("angle", 11, -180, 180);
  CellMesh m;
  tet_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  const int32_t first = tet_block(m, b.n, b.n, b.h, {0, 0, double(b.h)}, {1, 1, 1}, 0.5, b.n);
  // A rotation about a vertical axis keeps every z, so the interface stays exactly planar
  // and the cells keep their orientation.
  const double a = angle * std::acos(-1.0) / 180, c = std::cos(a), s = std::sin(a), mid = 0.5 * b.n;
  for (size_t i = static_cast<size_t>(first); i < m.points.size(); ++i) {
    Vec3& q = m.points[i];
    const double x = q.x - mid, y = q.y - mid;
    q.x = mid + c * x - s * y;
    q.y = mid + s * x + c * y;
  }
  return finish("touching-rotated", std::move(m), p);
}

Scene make_touching_overhang(Params& p) {
  const Base b = base(p);
  CellMesh m;
  tet_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  // n x n half-unit cells: side n/2, from x = 3n/4 to 5n/4 (beyond the lower block's n).
  tet_block(m, b.n, b.n, b.h, {0.75 * b.n, 0.25 * b.n, double(b.h)}, {0.5, 0.5, 0.5}, 0.5, b.n);
  return finish("touching-overhang", std::move(m), p);
}

Scene make_touching_edge(Params& p) {
  const Base b = base(p);
  CellMesh m;
  // A: [0,n] x [0,n] x [0,h]; B: [n, 1.5n] x [0,n] x [0,h] at half-unit cells;
  // C: [0,n] x [0.5, n+0.5] x [h, 2h]. A|B and B|C are separated by x = n, A|C by z = h.
  tet_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  tet_block(m, b.n, 2 * b.n, 2 * b.h, {double(b.n), 0, 0}, {0.5, 0.5, 0.5}, 0.4, b.n);
  tet_block(m, b.n, b.n, b.h, {0, 0.5, double(b.h)}, {1, 1, 1}, 0.6, b.n);
  return finish("touching-edge", std::move(m), p);
}

Scene make_touching_hex(Params& p) {
  const Base b = base(p);
  CellMesh m;
  hex_block(m, b.n, b.n, b.h, {0, 0, 0}, {1, 1, 1}, 0.2, b.n);
  hex_block(m, b.n, b.n, b.h, {0.5, 0.5, double(b.h)}, {1, 1, 1}, 0.5, b.n);
  return finish("touching-hex", std::move(m), p);
}

}  // namespace vob
