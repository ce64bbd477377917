#include "tests/algorithms/test_meshes.h"

#include <algorithm>
#include <cmath>

#include "harness/geometry/predicates.h"

namespace vob::testing {

CellMesh tet_block(int nx, int ny, int nz, Vec3 origin, double h) {
  CellMesh m;
  auto pid = [&](int i, int j, int k) { return static_cast<int32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.points.push_back(origin + Vec3{i * h, j * h, k * h});
  static const int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& perm : kPerm) {
          int c[3] = {i, j, k};
          int32_t v[4];
          v[0] = pid(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[perm[s]];
            v[s + 1] = pid(c[0], c[1], c[2]);
          }
          if (orient3d(m.points[v[0]], m.points[v[1]], m.points[v[2]], m.points[v[3]]) < 0)
            std::swap(v[1], v[2]);
          m.add_cell(CellType::Tetra, v);
        }
  return m;
}

CellMesh append(const CellMesh& a, const CellMesh& b) {
  CellMesh m = a;
  const auto shift = static_cast<int32_t>(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  for (size_t c = 0; c < b.num_cells(); ++c) {
    int32_t v[8];
    for (int i = 0; i < b.cell_size(c); ++i) v[i] = b.cell_points(c)[i] + shift;
    m.add_cell(b.types[c], v);
  }
  return m;
}

CellMesh two_blocks(int n, double gap) {
  return append(tet_block(n, n, n), tet_block(n, n, n, Vec3{n + gap, 0, 0}));
}

CellMesh blade_ring(int sectors) {
  constexpr double kPi = 3.14159265358979323846;
  const double r1 = 1, r2 = 2, rm = 1.5, h = 1;
  const double step = 2 * kPi / sectors, tilt = 0.3 * step;
  CellMesh m;
  for (int i = 0; i < sectors; ++i) {
    const double a = i * step;
    m.points.push_back({r1 * std::cos(a), r1 * std::sin(a), 0});                 // A_i
    m.points.push_back({r2 * std::cos(a), r2 * std::sin(a), 0});                 // B_i
    m.points.push_back({rm * std::cos(a - tilt), rm * std::sin(a - tilt), h});   // C_i
  }
  for (int i = 0; i < sectors; ++i) {
    const int32_t p = 3 * i, q = 3 * ((i + 1) % sectors);
    m.add_cell(CellType::Wedge, {p, p + 1, p + 2, q, q + 1, q + 2});
  }
  return m;
}

Camera ring_axis_view(bool ortho) {
  Camera c;
  c.eye = {0, 0, 8};
  c.target = {0, 0, 0.5};
  c.up = {0, 1, 0};
  c.ortho = ortho;
  c.ortho_height = 5;
  c.width = c.height = 64;
  return c;
}

RayCheck ray_check(const Scene& scene, const Camera& view, const std::vector<int32_t>& order) {
  const CellMesh& mesh = scene.mesh();
  const MeshFaces& faces = scene.faces();
  const FacePlanes& planes = scene.face_planes();
  const size_t n = mesh.num_cells();
  std::vector<int32_t> pos(n, -1);
  for (size_t i = 0; i < order.size(); ++i) pos[order[i]] = static_cast<int32_t>(i);
  const double scale = std::max(1.0, scene.bounds().radius());
  RayCheck out;
  struct Hit {
    double t;
    int32_t cell;
  };
  std::vector<Hit> hits;
  for (int j = 0; j < view.height; ++j)
    for (int i = 0; i < view.width; ++i) {
      const Ray ray = view.pixel_ray(i, j);
      hits.clear();
      for (size_t c = 0; c < n; ++c) {
        double t_in = 0, t_out = 1e300;
        for (int32_t k = faces.cell_face_offsets[c]; k < faces.cell_face_offsets[c + 1]; ++k) {
          const int32_t f = faces.cell_faces[k];
          const double sgn = faces.cell0[f] == static_cast<int32_t>(c) ? 1.0 : -1.0;
          const Vec3 nrm = planes.normal[f] * sgn;
          const double value = dot(nrm, ray.origin) + planes.offset[f] * sgn;
          const double denom = dot(nrm, ray.dir);
          if (denom < 0)
            t_in = std::max(t_in, -value / denom);
          else if (denom > 0)
            t_out = std::min(t_out, -value / denom);
          else if (value > 0)
            t_out = -1;
        }
        if (t_out - t_in > 1e-9 * scale) hits.push_back({0.5 * (t_in + t_out), static_cast<int32_t>(c)});
      }
      if (hits.empty()) continue;
      ++out.rays_hit;
      std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
      for (size_t a = 0; a < hits.size(); ++a)
        for (size_t b = a + 1; b < hits.size(); ++b) {
          ++out.pairs_checked;
          const int32_t near = hits[a].cell, far = hits[b].cell;
          // Back to front: the farther cell must be drawn first.
          if (pos[near] < pos[far]) out.violations.insert({near, far});
        }
    }
  return out;
}

int64_t face_arrow_violations(const Scene& scene, const Camera& view,
                              const std::vector<int32_t>& order) {
  const CellMesh& mesh = scene.mesh();
  const MeshFaces& faces = scene.faces();
  std::vector<int32_t> pos(mesh.num_cells(), -1);
  for (size_t i = 0; i < order.size(); ++i) pos[order[i]] = static_cast<int32_t>(i);
  int64_t bad = 0;
  for (size_t f = 0; f < faces.num_faces(); ++f) {
    if (faces.cell1[f] < 0) continue;
    const int32_t* v = faces.face_points(f);
    const Vec3 a = mesh.points[v[0]], b = mesh.points[v[1]], c = mesh.points[v[2]];
    const int s = view.ortho ? -orient_direction(a, b, c, view.forward())
                             : orient3d(a, b, c, view.eye);
    if (s == 0) continue;
    // s > 0: the eye is on cell1's side, cell0 is behind and must come first.
    const int32_t behind = s > 0 ? faces.cell0[f] : faces.cell1[f];
    const int32_t front = s > 0 ? faces.cell1[f] : faces.cell0[f];
    if (pos[behind] > pos[front]) ++bad;
  }
  return bad;
}

bool is_permutation_of(const std::vector<int32_t>& order, size_t n) {
  if (order.size() != n) return false;
  std::vector<uint8_t> seen(n, 0);
  for (int32_t id : order) {
    if (id < 0 || static_cast<size_t>(id) >= n || seen[id]) return false;
    seen[id] = 1;
  }
  return true;
}

}  // namespace vob::testing
