#include "datasets/generators/zoo.h"

#include <cmath>

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;

// One sphere of radius 1 at `centre`. Point ids: centre, then per layer k = 1..nr the north
// pole, the nlat-1 latitude rings of nlon points, and the south pole.
void append_sphere(CellMesh& m, Vec3 centre, int nlon, int nlat, int nr, double scalar_gain) {
  const auto c = static_cast<int32_t>(m.points.size());
  const int32_t per_layer = 2 + (nlat - 1) * nlon;
  m.points.push_back(centre);
  m.scalars.push_back(scalar_gain);
  for (int k = 1; k <= nr; ++k) {
    const double rho = double(k) / nr;
    const double s = scalar_gain * (1.0 - 0.8 * rho);
    m.points.push_back(centre + Vec3{0, 0, rho});
    m.scalars.push_back(s);
    for (int j = 1; j < nlat; ++j) {
      const double th = kPi * j / nlat;
      for (int i = 0; i < nlon; ++i) {
        const double ph = 2 * kPi * i / nlon;
        m.points.push_back(centre + Vec3{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                         std::cos(th)} * rho);
        m.scalars.push_back(s);
      }
    }
    m.points.push_back(centre + Vec3{0, 0, -rho});
    m.scalars.push_back(s);
  }
  auto north = [&](int k) { return c + 1 + (k - 1) * per_layer; };
  auto south = [&](int k) { return north(k) + per_layer - 1; };
  // Latitude row j in 1..nlat-1, longitude i wraps around.
  auto at = [&](int k, int j, int i) { return north(k) + 1 + (j - 1) * nlon + (i % nlon); };

  // Orientation: the loop (j,i) -> (j+1,i) -> (j+1,i+1) -> (j,i+1) turns counter-clockwise
  // seen from outside the sphere (e_theta x e_phi = e_r).
  for (int i = 0; i < nlon; ++i) {
    // Innermost layer: tetrahedra (vertex 3 on the side the base's normal points to).
    m.add_cell(CellType::Tetra, {north(1), at(1, 1, i + 1), at(1, 1, i), c});
    m.add_cell(CellType::Tetra, {at(1, nlat - 1, i), at(1, nlat - 1, i + 1), south(1), c});
    // Pyramids: the base normal points to the apex (the centre).
    for (int j = 1; j < nlat - 1; ++j)
      m.add_cell(CellType::Pyramid,
                 {at(1, j, i), at(1, j, i + 1), at(1, j + 1, i + 1), at(1, j + 1, i), c});
    // Outer layers: bottom (inner) faces have normals pointing away from the top for
    // wedges, into the cell for hexahedra (VTK conventions).
    for (int k = 1; k < nr; ++k) {
      m.add_cell(CellType::Wedge, {north(k), at(k, 1, i + 1), at(k, 1, i), north(k + 1),
                                   at(k + 1, 1, i + 1), at(k + 1, 1, i)});
      m.add_cell(CellType::Wedge,
                 {at(k, nlat - 1, i), at(k, nlat - 1, i + 1), south(k), at(k + 1, nlat - 1, i),
                  at(k + 1, nlat - 1, i + 1), south(k + 1)});
      for (int j = 1; j < nlat - 1; ++j)
        m.add_cell(CellType::Hexahedron,
                   {at(k, j, i), at(k, j + 1, i), at(k, j + 1, i + 1), at(k, j, i + 1),
                    at(k + 1, j, i), at(k + 1, j + 1, i), at(k + 1, j + 1, i + 1),
                    at(k + 1, j, i + 1)});
    }
  }
}
}  // namespace

CellMesh make_zoo_mesh(int scale) {
  const int nlon = 20 * scale, nlat = 10 * scale, nr = 6 * scale;
  const Vec3 centres[6] = {{1.6, 0, 0}, {-1.6, 0, 0}, {0, 1.6, 0},
                           {0, -1.6, 0}, {0, 0, 1.6}, {0, 0, -1.6}};
  CellMesh m;
  const int64_t cells_per = int64_t(nlon) * nlat * nr;
  m.types.reserve(6 * cells_per);
  m.offsets.reserve(6 * cells_per + 1);
  m.conn.reserve(6 * cells_per * 8);
  for (int s = 0; s < 6; ++s) append_sphere(m, centres[s], nlon, nlat, nr, 0.5 + 0.1 * s);
  return m;
}

Scene make_zoo(Params& p) {
  const int scale = p.get_int("scale", 1, 1, 10);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  return Scene::from_mesh("zoo", make_zoo_mesh(scale), p.to_json());
}

}  // namespace vob
