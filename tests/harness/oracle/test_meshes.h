// Small meshes and scenes with known exact orders, built here so that the raster, oracle
// and render tests do not depend on the dataset generators.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob::test {

inline double test_scalar(Vec3 p) { return p.x + 0.5 * p.y + std::sin(3.0 * p.z); }

// (n+1)^3 grid points on [0, n]^3 * h, optionally jittered (interior points only, by up to
// jitter * h per axis, deterministic).
inline std::vector<Vec3> grid_points(int n, double h, double jitter, uint32_t seed) {
  std::vector<Vec3> pts;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec3 p{i * h, j * h, k * h};
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        if (jitter > 0 && interior) p += Vec3{u(rng), u(rng), u(rng)};
        pts.push_back(p);
      }
  return pts;
}

inline int32_t grid_id(int n, int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); }

// An n^3 block of cubes, each split into the 6 Kuhn tetrahedra around its main diagonal
// (conforming across cubes). Cell 6*h + t is tet t of hex h = i + n*(j + n*k).
inline CellMesh tet_block(int n, double h = 1.0, double jitter = 0, uint32_t seed = 1) {
  CellMesh m;
  m.points = grid_points(n, h, jitter, seed);
  for (const Vec3& p : m.points) m.scalars.push_back(test_scalar(p));
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& pm : perms) {
          int c[3] = {i, j, k};
          int32_t v[4];
          v[0] = grid_id(n, c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[pm[s]];
            v[s + 1] = grid_id(n, c[0], c[1], c[2]);
          }
          const Vec3 a = m.points[v[0]];
          if (dot(cross(m.points[v[1]] - a, m.points[v[2]] - a), m.points[v[3]] - a) < 0)
            std::swap(v[1], v[2]);
          m.add_cell(CellType::Tetra, v);
        }
  return m;
}

// An n^3 block of axis-aligned hexahedra (planar faces). Cell i + n*(j + n*k).
inline CellMesh hex_block(int n, double h = 1.0) {
  CellMesh m;
  m.points = grid_points(n, h, 0, 1);
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

// Depth key of a point for a view: larger is farther. Sorting the cubes of a regular grid
// by it is exact (the grid is the Voronoi diagram of the cube centres).
inline double view_key(const Camera& cam, Vec3 p) {
  return cam.ortho ? dot(p - cam.eye, cam.forward()) : dot(p - cam.eye, p - cam.eye);
}

// Exact back-to-front order of tet_block(n) (unjittered) for `cam`: cubes by decreasing
// distance, the 6 tets of a cube topologically sorted by their shared faces.
inline std::vector<int32_t> tet_block_exact_order(const CellMesh& m, int n, const Camera& cam) {
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

inline Camera test_camera(Vec3 eye, Vec3 target, int w, int h, bool ortho = false,
                          double ortho_height = 2.0) {
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

}  // namespace vob::test
