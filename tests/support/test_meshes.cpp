#include "tests/support/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "harness/geometry/predicates.h"

namespace vob::test {
namespace {

// The Kuhn grid: (nx+1)(ny+1)(nz+1) points, interior ones jittered by up to jitter * h per
// axis (three draws per interior point in point order), 6 positively oriented tets a cube.
CellMesh kuhn_grid(int nx, int ny, int nz, Vec3 origin, double h, double jitter, uint32_t seed) {
  CellMesh m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
  auto pid = [&](int i, int j, int k) { return static_cast<int32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Vec3 p = origin + Vec3{i * h, j * h, k * h};
        const bool interior = i > 0 && i < nx && j > 0 && j < ny && k > 0 && k < nz;
        if (jitter > 0 && interior) p += Vec3{u(rng), u(rng), u(rng)};
        m.points.push_back(p);
      }
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

int32_t grid_id(int n, int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); }

}  // namespace

double test_scalar(Vec3 p) { return p.x + 0.5 * p.y + std::sin(3.0 * p.z); }

CellMesh tet_block(int nx, int ny, int nz, Vec3 origin, double h) {
  return kuhn_grid(nx, ny, nz, origin, h, 0, 1);
}

CellMesh kuhn_block(int n, double h, double jitter, uint32_t seed) {
  CellMesh m = kuhn_grid(n, n, n, {}, h, jitter, seed);
  for (const Vec3& p : m.points) m.scalars.push_back(test_scalar(p));
  return m;
}

Scene kuhn_block_scene(int n) {
  CellMesh m = kuhn_block(n);
  validate_cell_mesh(m, "tet block");
  return Scene::from_mesh("tet block", std::move(m));
}

CellMesh hex_block(int n, double h) {
  CellMesh m;
  m.points = kuhn_grid(n, n, n, {}, h, 0, 1).points;
  for (const Vec3& p : m.points) m.scalars.push_back(test_scalar(p));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int32_t v[8] = {grid_id(n, i, j, k),         grid_id(n, i + 1, j, k),
                              grid_id(n, i + 1, j + 1, k), grid_id(n, i, j + 1, k),
                              grid_id(n, i, j, k + 1),     grid_id(n, i + 1, j, k + 1),
                              grid_id(n, i + 1, j + 1, k + 1), grid_id(n, i, j + 1, k + 1)};
        m.add_cell(CellType::Hexahedron, v);
      }
  return m;
}

CellMesh twisted_hex_bar(int n, int layers, double twist) {
  CellMesh m;
  auto id = [&](int i, int j, int k) { return int32_t(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= layers; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = i - 0.5 * n, y = j - 0.5 * n, a = k * twist;
        m.points.push_back({x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a), double(k)});
        m.scalars.push_back(test_scalar(m.points.back()));
      }
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int32_t v[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        m.add_cell(CellType::Hexahedron, v);
      }
  return m;
}

CellMesh overlapping_twisted_bar(int layers, double twist) {
  CellMesh m = twisted_hex_bar(2, layers, twist);
  for (int k = 0; k <= layers; ++k) {
    const int32_t a = 9 * k + 5, b = 9 * k + 1;  // (2,1) and (1,0)
    std::swap(m.points[a], m.points[b]);
    std::swap(m.scalars[a], m.scalars[b]);
    for (int32_t& v : m.conn) v = v == a ? b : (v == b ? a : v);
  }
  return m;
}

CellMesh append(const CellMesh& a, const CellMesh& b) {
  CellMesh m = a;
  const int32_t base = int32_t(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  if (!a.scalars.empty() || !b.scalars.empty()) {
    m.scalars.resize(a.points.size(), 0.0);
    for (size_t i = 0; i < b.points.size(); ++i) m.scalars.push_back(b.scalar(i));
  }
  for (size_t c = 0; c < b.num_cells(); ++c) {
    int32_t ids[8];
    for (int i = 0; i < b.cell_size(c); ++i) ids[i] = b.cell_points(c)[i] + base;
    m.add_cell(b.types[c], ids);
  }
  return m;
}

CellMesh translated(CellMesh m, Vec3 by) {
  for (Vec3& p : m.points) p += by;
  return m;
}

CellMesh rotated(CellMesh m, Vec3 axis, double angle) {
  const Vec3 u = normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec3& p : m.points) p = p * c + cross(u, p) * s + u * (dot(u, p) * (1 - c));  // Rodrigues
  return m;
}

CellMesh two_blocks(int n, double gap) {
  return append(tet_block(n, n, n), tet_block(n, n, n, Vec3{n + gap, 0, 0}));
}

void add_tet(CellMesh& m, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (dot(cross(b - a, c - a), d - a) < 0) std::swap(b, c);
  const int32_t base = int32_t(m.points.size());
  for (const Vec3& p : {a, b, c, d}) m.points.push_back(p);
  m.add_cell(CellType::Tetra, {base, base + 1, base + 2, base + 3});
}

CellMesh tet_pair(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e, Vec3 f, Vec3 g, Vec3 h) {
  CellMesh m;
  add_tet(m, a, b, c, d);
  add_tet(m, e, f, g, h);
  return m;
}

// Two n^3 Kuhn blocks that interpenetrate: the second moved by (n/2 + 0.25, 0.3, 0.2) * h.
CellMesh interpenetrating_blocks(int n, double h) {
  const CellMesh a = kuhn_block(n, h);
  return append(a, translated(a, Vec3{(0.5 * n + 0.25) * h, 0.3 * h, 0.2 * h}));
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

Camera ring_axis_view(bool ortho) { return test_camera({0, 0, 8}, {0, 0, 0.5}, 64, 64, ortho, 5); }

double view_key(const Camera& cam, Vec3 p) {
  return cam.ortho ? dot(p - cam.eye, cam.forward()) : dot(p - cam.eye, p - cam.eye);
}

// Exact back-to-front order of kuhn_block(n) (unjittered) for `cam`: cubes by decreasing
// distance, the 6 tets of a cube topologically sorted by their shared faces.
std::vector<int32_t> tet_block_exact_order(const CellMesh& m, int n, const Camera& cam) {
  const int nh = n * n * n;
  std::vector<int32_t> hexes(nh);
  std::iota(hexes.begin(), hexes.end(), 0);
  std::vector<double> key(nh);
  for (int h = 0; h < nh; ++h) {
    Vec3 c;
    for (int t = 0; t < 6; ++t) c += m.cell_centroid(6 * h + t);
    key[h] = view_key(cam, c / 6.0);
  }
  std::stable_sort(hexes.begin(), hexes.end(), [&](int a, int b) { return key[a] > key[b]; });
  std::vector<int32_t> order;
  for (int h : hexes) {
    // behind[a][b]: tet a must be drawn before tet b (they share a face, b is in front).
    bool behind[6][6] = {};
    int indeg[6] = {};
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        if (a == b) continue;
        const int32_t* pa = m.cell_points(6 * h + a);
        const int32_t* pb = m.cell_points(6 * h + b);
        std::vector<int32_t> shared;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            if (pa[i] == pb[j]) shared.push_back(pa[i]);
        if (shared.size() != 3) continue;
        const Vec3 p0 = m.points[shared[0]], p1 = m.points[shared[1]], p2 = m.points[shared[2]];
        Vec3 nrm = cross(p1 - p0, p2 - p0);
        if (dot(nrm, m.cell_centroid(6 * h + a) - p0) > 0) nrm = -nrm;  // out of a, into b
        const double s = cam.ortho ? -dot(nrm, cam.forward()) : dot(nrm, cam.eye - p0);
        if (s > 0) behind[a][b] = true, ++indeg[b];
      }
    bool done[6] = {};
    for (int step = 0; step < 6; ++step) {
      int pick = -1;
      for (int a = 0; a < 6 && pick < 0; ++a)
        if (!done[a] && indeg[a] == 0) pick = a;
      if (pick < 0) return {};  // a cycle: cannot happen for a Kuhn cube
      done[pick] = true;
      order.push_back(6 * h + pick);
      for (int b = 0; b < 6; ++b)
        if (behind[pick][b]) --indeg[b];
    }
  }
  return order;
}

Camera test_camera(Vec3 eye, Vec3 target, int w, int h, bool ortho, double ortho_height) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = std::fabs(normalize(target - eye).z) > 0.99 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  c.width = w;
  c.height = h;
  c.ortho = ortho;
  c.ortho_height = ortho_height;
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

}  // namespace vob::test
