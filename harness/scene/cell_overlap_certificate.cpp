// The boundary certificate of cell_overlap.h (certify_cells_disjoint): boundary triangles
// against the cells their boxes meet, then one interior point per face-connected component.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Box_intersection_d/Box_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "harness/scene/cell_overlap.h"
#include "harness/scene/cell_overlap_detail.h"

namespace vob {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

using overlap_detail::sign_det;
using overlap_detail::type_shape;
using overlap_detail::TypeShape;
using Pairs = std::vector<std::pair<int32_t, int32_t>>;

// A boundary face triangle: its points and the cell that owns the face.
struct BoundaryTri {
  int32_t v[3];
  int32_t cell;
};

// A bounding box reporting by index (triangles, sample points).
// `key` is unique across both sequences of a bipartite search (CGAL breaks ties by it).
struct IndexBox : CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_NONE> {
  using Base = CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_NONE>;
  IndexBox(const CGAL::Bbox_3& b, int32_t i, size_t k) : Base(b), index(i), key(k) {}
  std::size_t id() const { return key; }
  int32_t index;
  size_t key;
};

CGAL::Bbox_3 point_box(const Vec3& p) { return CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z); }

CGAL::Bbox_3 cell_box(const CellMesh& mesh, size_t c) {
  const int32_t* ids = mesh.cell_points(c);
  CGAL::Bbox_3 bb = point_box(mesh.points[ids[0]]);
  for (int i = 1; i < mesh.cell_size(c); ++i) bb += point_box(mesh.points[ids[i]]);
  return bb;
}

bool face_neighbours(const MeshFaces& faces, int32_t a, int32_t b) {
  for (int32_t i = faces.cell_face_offsets[a]; i < faces.cell_face_offsets[a + 1]; ++i)
    if (faces.other(size_t(faces.cell_faces[i]), a) == b) return true;
  return false;
}

// A point strictly inside cell c (planar faces): its vertex mean, or failing that (rounding
// on a very thin cell) a mean weighted towards one vertex; false when none is. Exact test.
bool interior_point(const CellMesh& mesh, int32_t c, Vec3& out) {
  const int32_t* ids = mesh.cell_points(c);
  const int n = mesh.cell_size(c);
  const TypeShape& ts = type_shape(mesh.types[c]);
  for (int attempt = 0; attempt <= n; ++attempt) {
    Vec3 p{0, 0, 0};
    double wsum = 0;
    for (int i = 0; i < n; ++i) {
      const double w = (attempt > 0 && i == attempt - 1) ? double(n) : 1.0;
      p += mesh.points[ids[i]] * w;
      wsum += w;
    }
    p = p * (1.0 / wsum);
    bool inside = true;
    for (int t = 0; t < ts.ntri && inside; ++t) {
      const Vec3& a = mesh.points[ids[ts.tri[t][0]]];
      const Vec3& b = mesh.points[ids[ts.tri[t][1]]];
      const Vec3& d = mesh.points[ids[ts.tri[t][2]]];
      inside = sign_det(a, b, a, d, a, p) < 0;  // outward normals: beyond a face is positive
    }
    if (inside) {
      out = p;
      return true;
    }
  }
  return false;
}

struct UnionFind {
  std::vector<int32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int32_t find(int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int32_t a, int32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

OverlapCertificate certify_cells_disjoint(const CellMesh& mesh, const MeshFaces& faces) {
  const auto t0 = Clock::now();
  const std::clock_t cpu0 = std::clock();
  OverlapCertificate r;
  auto undecided = [&](std::string why) {
    r.result = OverlapCertificate::Undecided;
    r.why = std::move(why);
    r.seconds = since(t0);
    r.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    return r;
  };
  // The argument needs every cell to be the polyhedron its faces bound: planar quads.
  for (size_t f = 0; f < faces.num_faces(); ++f) {
    if (faces.face_size(f) != 4) continue;
    const int32_t* v = faces.face_points(f);
    const Vec3 &a = mesh.points[v[0]], &b = mesh.points[v[1]], &c = mesh.points[v[2]],
               &d = mesh.points[v[3]];
    if (sign_det(a, b, a, c, a, d) != 0) return undecided("a quad face is not planar");
  }

  // (1) Boundary triangles against the cells their closed boxes meet.
  std::vector<BoundaryTri> tris;
  tris.reserve(faces.boundary.size() * 2);
  for (int32_t f : faces.boundary) {
    const int32_t* v = faces.face_points(size_t(f));
    tris.push_back({{v[0], v[1], v[2]}, faces.cell0[f]});
    if (faces.face_size(size_t(f)) == 4) tris.push_back({{v[0], v[2], v[3]}, faces.cell0[f]});
  }
  r.boundary_triangles = int64_t(tris.size());
  std::vector<IndexBox> tri_boxes;  // cells' boxes are computed where needed
  tri_boxes.reserve(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) {
    CGAL::Bbox_3 bb = point_box(mesh.points[tris[i].v[0]]);
    bb += point_box(mesh.points[tris[i].v[1]]);
    bb += point_box(mesh.points[tris[i].v[2]]);
    tri_boxes.emplace_back(bb, int32_t(i), i);
  }

  // A pair (t, a) needs the exact cell test unless a is t's owner or its face neighbour, or
  // a plane keeps t out of a's interior: a lies on the closed outer side of t's plane, or t
  // on the closed outer side of a face plane of a without lying in it (cell_overlap.h).
  auto needs_test = [&](const BoundaryTri& t, int32_t a) {
    const int32_t e = t.cell;
    if (a == e || face_neighbours(faces, e, a)) return false;
    const Vec3 &t0p = mesh.points[t.v[0]], &t1p = mesh.points[t.v[1]], &t2p = mesh.points[t.v[2]];
    const int32_t* ids = mesh.cell_points(size_t(a));
    const int n = mesh.cell_size(size_t(a));
    bool inner = false;
    for (int i = 0; i < n && !inner; ++i) {
      const int32_t id = ids[i];
      if (id == t.v[0] || id == t.v[1] || id == t.v[2]) continue;
      inner = sign_det(t0p, t1p, t0p, t2p, t0p, mesh.points[id]) < 0;
    }
    if (!inner) return false;
    const TypeShape& ts = type_shape(mesh.types[size_t(a)]);
    for (int k = 0; k < ts.ntri; ++k) {
      const int32_t i0 = ids[ts.tri[k][0]], i1 = ids[ts.tri[k][1]], i2 = ids[ts.tri[k][2]];
      const Vec3 &f0 = mesh.points[i0], &f1 = mesh.points[i1], &f2 = mesh.points[i2];
      bool any_inner = false, any_outer = false;
      for (int j = 0; j < 3 && !any_inner; ++j) {
        const int32_t id = t.v[j];
        const int s = (id == i0 || id == i1 || id == i2)
                          ? 0
                          : sign_det(f0, f1, f0, f2, f0, mesh.points[id]);
        any_inner |= s < 0;
        any_outer |= s > 0;
      }
      if (!any_inner && any_outer) return false;
    }
    return true;
  };
  // The triangles' boxes in a uniform grid (about two grid cells per triangle); each mesh
  // cell visits the grid cells its box covers. A (triangle, cell) pair is looked at in the
  // grid cell holding the lower corner of the two boxes' intersection only.
  CGAL::Bbox_3 all;
  for (const IndexBox& b : tri_boxes) all += b.bbox();
  const double ext[3] = {all.xmax() - all.xmin(), all.ymax() - all.ymin(), all.zmax() - all.zmin()};
  const double lo[3] = {all.xmin(), all.ymin(), all.zmin()};
  int dim[3] = {1, 1, 1};
  double inv[3] = {0, 0, 0};
  if (!tris.empty()) {
    const double vol = std::max(ext[0], 1e-300) * std::max(ext[1], 1e-300) * std::max(ext[2], 1e-300);
    const double side = std::cbrt(vol / (2.0 * double(tris.size())));
    for (int k = 0; k < 3; ++k) {
      dim[k] = int(std::clamp(ext[k] / side, 1.0, 1024.0));
      inv[k] = ext[k] > 0 ? dim[k] / ext[k] : 0.0;
    }
  }
  auto slot = [&](int k, double x) {
    const double g = (x - lo[k]) * inv[k];
    return g <= 0 ? 0 : std::min(dim[k] - 1, int(g));
  };
  const size_t nslots = size_t(dim[0]) * dim[1] * dim[2];
  std::vector<int64_t> start(nslots + 1, 0);
  std::vector<int32_t> grid;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int64_t> fill;
    if (pass == 1) {
      for (size_t i = 0; i < nslots; ++i) start[i + 1] += start[i];
      grid.resize(size_t(start[nslots]));
      fill.assign(start.begin(), start.end() - 1);
    }
    for (size_t i = 0; i < tri_boxes.size(); ++i) {
      const CGAL::Bbox_3& b = tri_boxes[i].bbox();
      const int x0 = slot(0, b.xmin()), x1 = slot(0, b.xmax()), y0 = slot(1, b.ymin()),
                y1 = slot(1, b.ymax()), z0 = slot(2, b.zmin()), z1 = slot(2, b.zmax());
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const size_t g = size_t(x) + size_t(dim[0]) * (size_t(y) + size_t(dim[1]) * size_t(z));
            if (pass == 0) ++start[g + 1];
            else grid[size_t(fill[g]++)] = int32_t(i);
          }
    }
  }
  std::atomic<int64_t> looked{0};
  tbb::combinable<Pairs> survivors;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.empty() ? 0 : mesh.num_cells(), 1 << 12),
                    [&](const tbb::blocked_range<size_t>& range) {
                      Pairs& out = survivors.local();
                      int64_t n_looked = 0;
                      for (size_t c = range.begin(); c < range.end(); ++c) {
                        const CGAL::Bbox_3 cb = cell_box(mesh, c);
                        if (!CGAL::do_overlap(cb, all)) continue;
                        const int x0 = slot(0, cb.xmin()), x1 = slot(0, cb.xmax()),
                                  y0 = slot(1, cb.ymin()), y1 = slot(1, cb.ymax()),
                                  z0 = slot(2, cb.zmin()), z1 = slot(2, cb.zmax());
                        for (int z = z0; z <= z1; ++z)
                          for (int y = y0; y <= y1; ++y)
                            for (int x = x0; x <= x1; ++x) {
                              const size_t g = size_t(x) + size_t(dim[0]) * (size_t(y) + size_t(dim[1]) * size_t(z));
                              for (int64_t j = start[g]; j < start[g + 1]; ++j) {
                                const int32_t ti = grid[size_t(j)];
                                const CGAL::Bbox_3& tb = tri_boxes[size_t(ti)].bbox();
                                if (!CGAL::do_overlap(cb, tb)) continue;
                                if (slot(0, std::max(cb.xmin(), tb.xmin())) != x ||
                                    slot(1, std::max(cb.ymin(), tb.ymin())) != y ||
                                    slot(2, std::max(cb.zmin(), tb.zmin())) != z)
                                  continue;
                                ++n_looked;
                                const BoundaryTri& t = tris[size_t(ti)];
                                const int32_t a = int32_t(c);
                                if (needs_test(t, a))
                                  out.emplace_back(std::min(t.cell, a), std::max(t.cell, a));
                              }
                            }
                      }
                      looked += n_looked;
                    });
  r.triangle_cell_pairs = looked.load();
  Pairs cell_pairs;
  survivors.combine_each([&](const Pairs& p) { cell_pairs.insert(cell_pairs.end(), p.begin(), p.end()); });
  std::sort(cell_pairs.begin(), cell_pairs.end());
  cell_pairs.erase(std::unique(cell_pairs.begin(), cell_pairs.end()), cell_pairs.end());
  r.contact_pairs = int64_t(cell_pairs.size());

  // (2) One interior point per face-connected component of cells, tested against every
  // cell whose closed box contains it.
  UnionFind uf(mesh.num_cells());
  for (size_t f = 0; f < faces.num_faces(); ++f)
    if (faces.cell1[f] >= 0) uf.unite(faces.cell0[f], faces.cell1[f]);
  std::vector<int32_t> sample_cell;
  for (size_t c = 0; c < mesh.num_cells(); ++c)
    if (uf.find(int32_t(c)) == int32_t(c)) sample_cell.push_back(int32_t(c));
  r.components = int64_t(sample_cell.size());
  std::vector<Vec3> sample(sample_cell.size());
  for (size_t i = 0; i < sample.size(); ++i)
    if (!interior_point(mesh, sample_cell[i], sample[i]))
      return undecided("no interior point found in cell " + std::to_string(sample_cell[i]));
  Pairs nest_pairs;  // (sample index, cell)
  auto contains = [](const CGAL::Bbox_3& b, const Vec3& p) {
    return b.xmin() <= p.x && p.x <= b.xmax() && b.ymin() <= p.y && p.y <= b.ymax() &&
           b.zmin() <= p.z && p.z <= b.zmax();
  };
  if (sample.size() <= 16) {
    for (size_t c = 0; c < mesh.num_cells(); ++c) {
      const CGAL::Bbox_3 cb = cell_box(mesh, c);
      for (size_t i = 0; i < sample.size(); ++i)
        if (contains(cb, sample[i])) nest_pairs.emplace_back(int32_t(i), int32_t(c));
    }
  } else {
    std::vector<IndexBox> points;
    for (size_t i = 0; i < sample.size(); ++i)
      points.emplace_back(point_box(sample[i]), int32_t(i), i);
    std::vector<IndexBox> cell_boxes;
    cell_boxes.reserve(mesh.num_cells());
    for (size_t c = 0; c < mesh.num_cells(); ++c)
      cell_boxes.emplace_back(cell_box(mesh, c), int32_t(c), sample.size() + c);
    CGAL::box_intersection_d(
        points.begin(), points.end(), cell_boxes.begin(), cell_boxes.end(),
        [&](const IndexBox& p, const IndexBox& c) { nest_pairs.emplace_back(p.index, c.index); },
        CGAL::Box_intersection_d::Box_traits_d<IndexBox>(), std::ptrdiff_t(10),
        CGAL::Box_intersection_d::CLOSED, CGAL::Box_intersection_d::BIPARTITE);
  }
  for (const auto& [i, c] : nest_pairs) {
    const int32_t s = sample_cell[size_t(i)];
    if (c == s) continue;
    cell_pairs.emplace_back(std::min(s, c), std::max(s, c));
    ++r.nesting_pairs;
  }

  // Exact decisions: every pair of (1) and (2).
  std::sort(cell_pairs.begin(), cell_pairs.end());
  cell_pairs.erase(std::unique(cell_pairs.begin(), cell_pairs.end()), cell_pairs.end());
  tbb::combinable<Pairs> bad;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, cell_pairs.size(), 256),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i < range.end(); ++i)
                        if (cells_interpenetrate(mesh, cell_pairs[i].first, cell_pairs[i].second))
                          bad.local().push_back(cell_pairs[i]);
                    });
  Pairs found;
  bad.combine_each([&](const Pairs& p) { found.insert(found.end(), p.begin(), p.end()); });
  r.result = found.empty() ? OverlapCertificate::Clean : OverlapCertificate::Overlap;
  if (!found.empty()) r.witness = *std::min_element(found.begin(), found.end());
  r.seconds = since(t0);
  r.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return r;
}

}  // namespace vob
