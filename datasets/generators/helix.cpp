#include "datasets/generators/helix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "datasets/generators/prism_split.h"
#include "datasets/generators/shuffle.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kMinStepsPerTurn = 6;
constexpr HelixShape kShape{};
static_assert(kShape.inner_radius < kShape.hole_radius && kShape.hole_radius < kShape.outer_radius);
// Adjacent turns (perpendicular spacing ~ pitch * cos(pitch angle) ~ 2.9) stay apart.
static_assert(2 * kShape.outer_radius < 0.95 * kShape.pitch && kShape.outer_radius < kShape.coil_radius);

// A cross-section in the sweep frame: points at (radius, angle) with scalars, and
// triangles clockwise in (U, V) so that each prism's bottom faces backwards along the sweep
// (VTK wedge orientation).
struct Section {
  std::vector<double> radius, angle, scalar;
  std::vector<std::array<int32_t, 3>> tris;
};

// Rings of `sectors` points at radii r[0] < r[1] < ... (scalars s, one per ring) with quads
// between consecutive rings; with `centre`, first a centre point (scalar centre_scalar)
// joined to ring 0 by a fan.
Section ring_section(bool centre, double centre_scalar, const std::vector<double>& r,
                     const std::vector<double>& s, int sectors) {
  Section sec;
  const int ns = sectors, nr = static_cast<int>(r.size());
  if (centre) {
    sec.radius.push_back(0);
    sec.angle.push_back(0);
    sec.scalar.push_back(centre_scalar);
  }
  const int base = centre ? 1 : 0;
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < ns; ++j) {
      sec.radius.push_back(r[i]);
      sec.angle.push_back(2 * kPi * j / ns);
      sec.scalar.push_back(s[i]);
    }
  auto id = [&](int ring, int sector) { return base + ring * ns + sector % ns; };
  if (centre)
    for (int j = 0; j < ns; ++j) sec.tris.push_back({0, id(0, j + 1), id(0, j)});
  for (int i = 0; i + 1 < nr; ++i)
    for (int j = 0; j < ns; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      sec.tris.push_back({a, c, b});
      sec.tris.push_back({a, d, c});
    }
  return sec;
}

// Inner tube: a disk, scalar 0.3 on the centre line falling to 0.2 at its surface.
Section inner_section(const HelixResolution& res) {
  std::vector<double> r, s;
  for (int i = 1; i <= res.inner_rings; ++i) {
    r.push_back(kShape.inner_radius * i / res.inner_rings);
    s.push_back(0.3 - 0.1 * i / res.inner_rings);
  }
  return ring_section(true, 0.3, r, s, res.sectors);
}

// Outer tube: an annulus from the bore to the outside, scalar 0.8 at the bore falling to
// 0.7 outside. Its bore polygon has the same angles as the inner tube's rim, so in every
// section the rim is the bore scaled by inner/hole radius and the film between them is at
// least (hole - inner radius) * cos(pi / sectors) thick: thin, but never closed.
Section outer_section(const HelixResolution& res) {
  std::vector<double> r, s;
  for (int i = 0; i <= res.outer_layers; ++i) {
    r.push_back(kShape.hole_radius + (kShape.outer_radius - kShape.hole_radius) * i / res.outer_layers);
    s.push_back(0.8 - 0.1 * i / res.outer_layers);
  }
  return ring_section(false, 0, r, s, res.sectors);
}

// Sweeps `sec` along the centre line in `steps` steps; every swept triangle is a prism cut
// into three tetrahedra with the conforming min-id rule (prism_split.h).
void sweep(CellMesh& m, const Section& sec, int steps, int turns, Vec3 offset) {
  const auto per_section = static_cast<int32_t>(sec.radius.size());
  const auto first = static_cast<int32_t>(m.points.size());
  const double R = kShape.coil_radius, b = kShape.pitch / (2 * kPi), L = std::sqrt(R * R + b * b);
  const double span = 2 * kPi * turns;
  std::vector<double> x(per_section), y(per_section);
  for (int32_t q = 0; q < per_section; ++q) {
    x[q] = sec.radius[q] * std::cos(sec.angle[q]);
    y[q] = sec.radius[q] * std::sin(sec.angle[q]);
  }
  for (int k = 0; k <= steps; ++k) {
    const double t = span * k / steps;
    const Vec3 c = helix_centre(t);
    const Vec3 n{-std::cos(t), -std::sin(t), 0};
    const Vec3 bn{b * std::sin(t) / L, -b * std::cos(t) / L, R / L};
    // Rotation-minimising frame: the Frenet frame turned back by the torsion angle, so
    // consecutive sections do not twist about the tangent (twisted prisms would invert).
    const double th = -b * t / L;
    const Vec3 U = n * std::cos(th) + bn * std::sin(th), V = bn * std::cos(th) - n * std::sin(th);
    for (int32_t q = 0; q < per_section; ++q) {
      m.points.push_back(offset + c + U * x[q] + V * y[q]);
      m.scalars.push_back(sec.scalar[q]);
    }
  }
  for (int k = 0; k < steps; ++k) {
    const int32_t lo = first + k * per_section, hi = lo + per_section;
    for (const auto& tr : sec.tris) {
      const int32_t ids[6] = {lo + tr[0], lo + tr[1], lo + tr[2], hi + tr[0], hi + tr[1], hi + tr[2]};
      int32_t tets[3][4];
      split_prism(ids, tets);
      for (const auto& tet : tets) m.add_cell(CellType::Tetra, tet);
    }
  }
}

// Arc between sectors at mid-wall: the cell size every count is derived from.
double cell_size(int sectors) { return kPi * (kShape.hole_radius + kShape.outer_radius) / sectors; }

// Rings and wall layers for `sectors`, cells near-isotropic (steps are set by the caller).
HelixResolution cross_section(int sectors) {
  HelixResolution r;
  r.sectors = sectors;
  const double h = cell_size(sectors);
  r.inner_rings = std::max(1, static_cast<int>(std::lround(kShape.inner_radius / h)));
  r.outer_layers = std::max(1, static_cast<int>(std::lround((kShape.outer_radius - kShape.hole_radius) / h)));
  return r;
}

double centre_line_length(int turns) {
  const double b = kShape.pitch / (2 * kPi);
  return 2 * kPi * turns * std::sqrt(kShape.coil_radius * kShape.coil_radius + b * b);
}
}  // namespace

Vec3 helix_centre(double t) {
  return {kShape.coil_radius * std::cos(t), kShape.coil_radius * std::sin(t), kShape.pitch * t / (2 * kPi)};
}

int helix_min_cells(int turns) {
  HelixResolution r = cross_section(3);
  r.steps = kMinStepsPerTurn * turns;
  return static_cast<int>(r.cells());
}

HelixResolution helix_resolution(int cells, int turns) {
  if (cells < helix_min_cells(turns))
    throw InputError("helix", "parameter cells",
                     std::to_string(cells) + " is below the smallest helix with " +
                         std::to_string(turns) + " turns (" +
                         std::to_string(helix_min_cells(turns)) + " cells)");
  const double length = centre_line_length(turns);
  // The sector count whose isotropic helix (steps as long as the cell size) is nearest
  // `cells`; then steps absorb the remainder, with fewer sectors when that would leave
  // fewer than kMinStepsPerTurn steps per turn.
  auto isotropic = [&](int ns) {
    HelixResolution r = cross_section(ns);
    r.steps = std::max(1, static_cast<int>(std::lround(length / cell_size(ns))));
    return double(r.cells());
  };
  int ns = 3;
  while (isotropic(ns + 1) <= cells) ++ns;
  if (isotropic(ns + 1) / cells < cells / isotropic(ns)) ++ns;
  HelixResolution r;
  for (; ns >= 3; --ns) {
    r = cross_section(ns);
    r.steps = static_cast<int>(std::lround(double(cells) / r.per_step()));
    if (r.steps >= kMinStepsPerTurn * turns) break;
  }
  return r;
}

int64_t helix_exterior_faces(const HelixResolution& r) {
  // Per step 2 * sectors triangles on each of the inner tube's surface, the bore and the
  // outside; each end is one cross-section of both tubes (per_step / 3 triangles).
  return int64_t(6) * r.sectors * r.steps + 2 * (r.per_step() / 3);
}

HelixResolution helix_resolution_for_faces(int cells, int faces, int turns) {
  const double n = cells, b = faces, length = centre_line_length(turns);
  const int min_steps = kMinStepsPerTurn * turns;
  HelixResolution best;
  double best_error = 1e300, best_aspect = 1e300;
  // b ~ 6 sectors steps: sectors beyond b / (6 min_steps) leave too few steps.
  const int max_sectors = std::max(3, static_cast<int>(b / (6.0 * min_steps)) + 1);
  for (int ns = 3; ns <= max_sectors; ++ns)
    // m = 2 rings - 1 + 2 layers (odd): triangles of one cross-section per sector.
    for (int m = 3; 3.0 * ns * m * min_steps <= 1.05 * n; m += 2) {
      HelixResolution r;
      r.sectors = ns;
      const int radial = (m + 1) / 2;  // rings + layers, split by the radii they span
      r.outer_layers = std::clamp(static_cast<int>(std::lround(
                                      radial * (kShape.outer_radius - kShape.hole_radius) /
                                      (kShape.outer_radius - kShape.hole_radius + kShape.inner_radius))),
                                  1, radial - 1);
      r.inner_rings = radial - r.outer_layers;
      r.steps = std::max(min_steps, static_cast<int>(std::lround(n / r.per_step())));
      const double error = std::max(std::fabs(r.cells() / n - 1), std::fabs(helix_exterior_faces(r) / b - 1));
      const double aspect = std::fabs(std::log(cell_size(ns) / (length / r.steps)));
      // Within 1% of both targets the squarest surface cells win; above, the nearer counts.
      const bool close = error <= 0.01, best_close = best_error <= 0.01;
      if (close != best_close ? close : close ? aspect < best_aspect : error < best_error) {
        best = r;
        best_error = error;
        best_aspect = aspect;
      }
    }
  if (best_error > 0.05)
    throw InputError("helix", "parameter faces",
                     std::to_string(faces) + " exterior faces with " + std::to_string(cells) +
                         " cells: no helix of " + std::to_string(turns) +
                         " turns comes within 5% of both (nearest: " + std::to_string(best.cells()) +
                         " cells, " + std::to_string(helix_exterior_faces(best)) + " faces)");
  return best;
}

CellMesh make_helix_mesh(const HelixSpec& s) {
  const HelixResolution r =
      s.faces > 0 ? helix_resolution_for_faces(s.cells, s.faces, s.turns) : helix_resolution(s.cells, s.turns);
  const Section inner = inner_section(r), outer = outer_section(r);
  CellMesh m;
  const int64_t cells = r.cells();
  const int64_t points = int64_t(r.steps + 1) * int64_t(inner.radius.size() + outer.radius.size());
  m.points.reserve(points);
  m.scalars.reserve(points);
  m.types.reserve(cells);
  m.offsets.reserve(cells + 1);
  m.conn.reserve(4 * cells);
  sweep(m, inner, r.steps, s.turns, s.offset);
  sweep(m, outer, r.steps, s.turns, s.offset);
  return m;
}

Scene make_helix(Params& p) {
  HelixSpec s;
  s.turns = p.get_int("turns", 3, 1, 20);
  s.cells = p.get_int("cells", 20000, helix_min_cells(s.turns), 50000000);
  s.faces = p.get_int("faces", 0, 0, 50000000);
  if (s.faces > 0) helix_resolution_for_faces(s.cells, s.faces, s.turns);  // InputError now
  const int shuffle = read_shuffle_param(p);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m = make_helix_mesh(s);
  if (shuffle > 0) m = shuffle_numbering(m, static_cast<uint64_t>(shuffle));
  return Scene::from_mesh("helix", std::move(m), p.to_json());
}

}  // namespace vob
