#include "datasets/generators/helix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "datasets/generators/prism_split.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kPitch = 3.0;
constexpr int kMinStepsPerTurn = 6;

struct Tube {
  double coil_radius, tube_radius, phase, scalar_lo, scalar_hi;
};
// Radial gap >= (2.4 - 0.6) - sqrt((1 + 0.35)^2 + (0.35 sin a)^2) > 0.44 (a: pitch angle).
constexpr Tube kInner{1.0, 0.35, 0.0, 0.2, 0.3};
constexpr Tube kOuter{2.4, 0.6, kPi, 0.7, 0.8};

void append_tube(CellMesh& m, const Tube& tube, const HelixResolution& res, int turns,
                 Vec3 offset) {
  const int ns = res.sectors, nr = res.rings, nt = res.steps;
  const int32_t per_section = 1 + ns * nr;
  const auto first = static_cast<int32_t>(m.points.size());
  const double R = tube.coil_radius, b = kPitch / (2 * kPi), L = std::sqrt(R * R + b * b);
  const double span = 2 * kPi * turns;
  for (int k = 0; k <= nt; ++k) {
    const double u = span * k / nt, t = tube.phase + u;
    const Vec3 c{R * std::cos(t), R * std::sin(t), b * u};
    const Vec3 n{-std::cos(t), -std::sin(t), 0};
    const Vec3 bn{b * std::sin(t) / L, -b * std::cos(t) / L, R / L};
    // Rotation-minimising frame: the Frenet frame turned back by the torsion angle, so
    // consecutive sections do not twist about the tangent (twisted prisms would invert).
    const double th = -b * u / L;
    const Vec3 U = n * std::cos(th) + bn * std::sin(th), V = bn * std::cos(th) - n * std::sin(th);
    m.points.push_back(offset + c);
    m.scalars.push_back(tube.scalar_hi);
    for (int i = 1; i <= nr; ++i) {
      const double rho = tube.tube_radius * i / nr;
      const double s = tube.scalar_hi - (tube.scalar_hi - tube.scalar_lo) * i / nr;
      for (int j = 0; j < ns; ++j) {
        const double phi = 2 * kPi * j / ns;
        m.points.push_back(offset + c + (U * std::cos(phi) + V * std::sin(phi)) * rho);
        m.scalars.push_back(s);
      }
    }
  }
  // Section triangles, clockwise in (U, V) so that each prism's bottom faces backwards
  // along the sweep (VTK wedge orientation).
  auto id = [&](int ring, int sector) { return ring == 0 ? 0 : 1 + (ring - 1) * ns + sector % ns; };
  std::vector<std::array<int32_t, 3>> tris;
  tris.reserve(size_t(ns) * (2 * nr - 1));
  for (int j = 0; j < ns; ++j) tris.push_back({0, id(1, j + 1), id(1, j)});
  for (int i = 1; i < nr; ++i)
    for (int j = 0; j < ns; ++j) {
      const int a = id(i, j), bb = id(i + 1, j), cc = id(i + 1, j + 1), d = id(i, j + 1);
      tris.push_back({a, cc, bb});
      tris.push_back({a, d, cc});
    }
  for (int k = 0; k < nt; ++k) {
    const int32_t lo = first + k * per_section, hi = lo + per_section;
    for (const auto& tr : tris) {
      const int32_t ids[6] = {lo + tr[0], lo + tr[1], lo + tr[2], hi + tr[0], hi + tr[1], hi + tr[2]};
      int32_t tets[3][4];
      split_prism(ids, tets);
      for (const auto& tet : tets) m.add_cell(CellType::Tetra, tet);
    }
  }
}
}  // namespace

int helix_min_cells(int turns) { return 2 * 3 * 3 * kMinStepsPerTurn * turns; }

HelixResolution helix_resolution(int cells, int turns) {
  if (cells < helix_min_cells(turns))
    throw InputError("helix", "parameter cells",
                     std::to_string(cells) + " is below the smallest helix with " +
                         std::to_string(turns) + " turns (" +
                         std::to_string(helix_min_cells(turns)) + " cells)");
  // Near-isotropic cells: rings ~ sectors/(2 pi), steps ~ 11 sectors (the tubes are about
  // 11 circumferences long), so cells ~ 21 sectors^3; then steps absorb the remainder.
  HelixResolution r;
  for (int ns = std::max(3, static_cast<int>(std::lround(std::cbrt(cells / 21.0)))); ns >= 3; --ns) {
    r.sectors = ns;
    r.rings = std::max(1, static_cast<int>(std::lround(ns / (2 * kPi))));
    const int per_step = 6 * ns * (2 * r.rings - 1);
    r.steps = static_cast<int>(std::lround(double(cells) / per_step));
    if (r.steps >= kMinStepsPerTurn * turns) break;
  }
  return r;
}

CellMesh make_helix_mesh(const HelixSpec& s) {
  const HelixResolution r = helix_resolution(s.cells, s.turns);
  CellMesh m;
  const int64_t cells = r.cells();
  const int64_t points = int64_t(2) * (r.steps + 1) * (1 + r.sectors * r.rings);
  m.points.reserve(points);
  m.scalars.reserve(points);
  m.types.reserve(cells);
  m.offsets.reserve(cells + 1);
  m.conn.reserve(4 * cells);
  append_tube(m, kInner, r, s.turns, s.offset);
  append_tube(m, kOuter, r, s.turns, s.offset);
  return m;
}

Scene make_helix(Params& p) {
  HelixSpec s;
  s.turns = p.get_int("turns", 3, 1, 20);
  s.cells = p.get_int("cells", 20000, helix_min_cells(s.turns), 50000000);
  return Scene::from_mesh("helix", make_helix_mesh(s), p.to_json());
}

}  // namespace vob
