#include "datasets/generators/cycles.h"

#include <cmath>

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;

Camera top_view(Vec3 eye, Vec3 target, double fov, int width, int height) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = {0, 1, 0};
  c.fov_deg = fov;
  c.width = width;
  c.height = height;
  return c;
}
}  // namespace

Scene make_cycle(Params& p) {
  const int k = p.get_int("cells", 6, 6, 64);  // with twist <= 30: convex for k >= 6
  const double twist = p.get_double("twist", 30.0, 5.0, 30.0) * kPi / 180.0;
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m;
  // Points: per separating segment i, inner a_i and outer b_i at z=1, then both at z=2
  // (the same directions from the apex, doubled).
  for (int layer = 1; layer <= 2; ++layer)
    for (int i = 0; i < k; ++i) {
      const double th = 2 * kPi * i / k;
      m.points.push_back(Vec3{std::cos(th), std::sin(th), 1.0} * layer);
      m.points.push_back(Vec3{2 * std::cos(th + twist), 2 * std::sin(th + twist), 1.0} * layer);
      m.scalars.push_back(0.5 + 0.3 * std::cos(th));
      m.scalars.push_back(0.5 + 0.3 * std::cos(th + twist));
    }
  auto a = [&](int layer, int i) { return static_cast<int32_t>(2 * k * (layer - 1) + 2 * (i % k)); };
  auto b = [&](int layer, int i) { return a(layer, i) + 1; };
  // The bottom quad a_i, b_i, b_i+1, a_i+1 turns counter-clockwise seen from above, so its
  // normal points into the cell (VTK hexahedron order).
  for (int i = 0; i < k; ++i)
    m.add_cell(CellType::Hexahedron, {a(1, i), b(1, i), b(1, i + 1), a(1, i + 1), a(2, i),
                                      b(2, i), b(2, i + 1), a(2, i + 1)});
  return Scene::from_mesh("cycle", std::move(m), p.to_json());
}

std::vector<Camera> cycle_views(const Scene& s, int width, int height) {
  // Any eye on the positive z axis sees every separating plane from the same side.
  const double r = 4.2, h = 8.0;
  std::vector<Camera> v;
  v.push_back(top_view({0, 0, h}, {0, 0, 1.5}, 2 * std::atan(r / (h - 2)) * 180 / kPi * 1.1,
                       width, height));
  Camera o = top_view({0, 0, h}, {0, 0, 0}, 40, width, height);
  o.ortho = true;
  o.ortho_height = 2 * r;
  v.push_back(o);
  return v;
}

Scene make_cycle_sticks(Params& p) {
  // Sides of a triangle around the incircle of radius d: stick i lies on the line
  // n_i . x = d, runs along u_i for t in [-len, len] at height slope * t. Lines i and i+1
  // cross at t_i = +sqrt(3) d and t_i+1 = -sqrt(3) d, so stick i is 2 sqrt(3) d slope
  // higher there: 1.04 apart, far more than thickness plus the rise across a stick width.
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  const double d = 1.0, slope = 0.3, len = 3.0, width = 0.3, thick = 0.2;
  CellMesh m;
  for (int i = 0; i < 3; ++i) {
    const double al = 2 * kPi * i / 3;
    const Vec3 n{std::cos(al), std::sin(al), 0}, u{-std::sin(al), std::cos(al), 0};
    const auto first = static_cast<int32_t>(m.points.size());
    // Order: bottom quad counter-clockwise from above (first along n, then along u).
    const double ts[4] = {-len, -len, len, len}, es[4] = {-width / 2, width / 2, width / 2, -width / 2};
    for (double v : {-thick / 2, thick / 2})
      for (int q = 0; q < 4; ++q) {
        m.points.push_back(n * (d + es[q]) + u * ts[q] + Vec3{0, 0, slope * ts[q] + v});
        m.scalars.push_back(0.3 + 0.3 * i);
      }
    m.add_cell(CellType::Hexahedron, {first, first + 1, first + 2, first + 3, first + 4,
                                      first + 5, first + 6, first + 7});
  }
  return Scene::from_mesh("cycle-sticks", std::move(m), p.to_json());
}

std::vector<Camera> cycle_sticks_views(const Scene& s, int width, int height) {
  std::vector<Camera> v;
  v.push_back(top_view({0, 0, 10}, {0, 0, 0}, 45, width, height));
  Camera o = top_view({0, 0, 10}, {0, 0, 0}, 40, width, height);
  o.ortho = true;
  o.ortho_height = 8;
  v.push_back(o);
  return v;
}

}  // namespace vob
