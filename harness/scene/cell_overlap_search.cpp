// The exhaustive overlap search of cell_overlap.h (every candidate pair from CGAL's box
// self-intersection, decided exactly), and the default check that tries the boundary
// certificate first.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Box_intersection_d/Box_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "harness/scene/cell_overlap.h"
#include "harness/scene/cell_overlap_detail.h"

namespace vob {
namespace {

// A bounding box that knows its cell (the id the box intersection reports pairs by).
struct CellBox : CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_NONE> {
  using Base = CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_NONE>;
  CellBox(const CGAL::Bbox_3& b, int32_t c) : Base(b), cell(c) {}
  std::size_t id() const { return std::size_t(cell); }
  int32_t cell;
};

using Pairs = std::vector<std::pair<int32_t, int32_t>>;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

CellOverlapReport find_overlapping_cells(const CellMesh& mesh) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  CellOverlapReport r;
  const size_t nc = mesh.num_cells();
  // Cells with a warped quad, and their models in the oracle's terms (cell_overlap.h,
  // "Warped quads"; a partner without one gets its model when a pair needs it). None of it
  // for a mesh whose quads are all exactly planar but the planarity test.
  // (The pair test takes each cell's non-planar quads from here instead of finding them
  // again per pair.)
  std::vector<uint8_t> warped(nc, 0);  // non_planar_quads: bit f for local face f
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nc, 4096), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t c = range.begin(); c < range.end(); ++c)
      warped[c] = overlap_detail::non_planar_quads(mesh, int32_t(c));
  });
  r.warped_cells = nc - std::count(warped.begin(), warped.end(), uint8_t(0));
  std::vector<int32_t> model_of;  // cell -> index into models, -1 if not warped
  std::vector<overlap_detail::ModelCell> models;
  Aabb all;
  if (r.warped_cells > 0) {
    r.model_tolerance = model_overlap_tolerance(mesh);
    all = mesh.bounds();
    model_of.assign(nc, -1);
    for (size_t c = 0; c < nc; ++c)
      if (warped[c]) model_of[c] = int32_t(models.size()), models.emplace_back();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nc, 1024), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t c = range.begin(); c < range.end(); ++c)
        if (warped[c]) models[model_of[c]] = overlap_detail::model_cell(mesh, int32_t(c));
    });
  }
  std::vector<CellBox> boxes;
  boxes.reserve(nc);
  for (size_t c = 0; c < nc; ++c) {
    const int32_t* ids = mesh.cell_points(c);
    CGAL::Bbox_3 bb;
    for (int i = 0; i < mesh.cell_size(c); ++i) {
      const Vec3& p = mesh.points[ids[i]];
      bb += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
    }
    if (warped[c]) {
      // The model polyhedron may reach past the vertices (unbounded, anywhere). Only an
      // overlap holding a cube of side > tol counts, and such a cube lies in both cells'
      // boxes: boxes shrunk by tol / 2 still overlap with positive volume. Shrunk, the box
      // of a cell warped only by rounding adds nothing to its vertices' box.
      const overlap_detail::ModelCell& mc = models[model_of[c]];
      const Aabb& m = mc.bounded ? mc.box : all;
      const double s = 0.5 * r.model_tolerance;
      if (m.lo.x + s < m.hi.x - s && m.lo.y + s < m.hi.y - s && m.lo.z + s < m.hi.z - s)
        bb += CGAL::Bbox_3(m.lo.x + s, m.lo.y + s, m.lo.z + s, m.hi.x - s, m.hi.y - s, m.hi.z - s);
    }
    boxes.emplace_back(bb, int32_t(c));
  }

  // Candidates fill a batch; a full batch is decided in parallel while the enumeration
  // fills the next one.
  constexpr size_t kBatch = size_t(1) << 20;
  Pairs filling, deciding;
  filling.reserve(kBatch);
  deciding.reserve(kBatch);
  tbb::combinable<Pairs> found;
  struct ModelFound {
    std::vector<CellOverlapReport::ModelPair> pairs;
    int64_t tests = 0, lps = 0;
  };
  tbb::combinable<ModelFound> model_found;
  const double tol = r.model_tolerance;
  tbb::task_group decide;
  auto launch = [&] {
    decide.wait();
    std::swap(filling, deciding);
    filling.clear();
    r.candidates += int64_t(deciding.size());
    decide.run([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, deciding.size(), 4096),
                        [&](const tbb::blocked_range<size_t>& range) {
                          Pairs& out = found.local();
                          for (size_t i = range.begin(); i < range.end(); ++i) {
                            const auto [a, b] = deciding[i];
                            const std::pair<int32_t, int32_t> ab(std::min(a, b), std::max(a, b));
                            if (overlap_detail::cells_interpenetrate(mesh, a, b, warped[a], warped[b])) {
                              out.push_back(ab);
                            } else if (warped[a] || warped[b]) {
                              ModelFound& mf = model_found.local();
                              overlap_detail::ModelCell own;  // a partner without a warped quad
                              auto model = [&](int32_t c) -> const overlap_detail::ModelCell* {
                                if (warped[c]) return &models[model_of[c]];
                                own = overlap_detail::model_cell(mesh, c);
                                return &own;
                              };
                              const overlap_detail::ModelCell* ma = model(a);
                              const overlap_detail::ModelCell* mb = model(b);
                              const ModelOverlap o = overlap_detail::model_overlap(mesh, a, b, ma, mb, tol);
                              ++mf.tests;
                              mf.lps += o.solved;
                              if (o.overlap) {
                                out.push_back(ab);
                                mf.pairs.push_back({ab, o.thickness});
                              }
                            }
                          }
                        });
    });
  };
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&](const CellBox& a, const CellBox& b) {
        filling.emplace_back(a.cell, b.cell);
        if (filling.size() == kBatch) launch();
      },
      CGAL::Box_intersection_d::Box_traits_d<CellBox>(), std::ptrdiff_t(10),
      CGAL::Box_intersection_d::HALF_OPEN);
  r.box_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  launch();
  decide.wait();
  found.combine_each([&](const Pairs& p) { r.pairs.insert(r.pairs.end(), p.begin(), p.end()); });
  std::sort(r.pairs.begin(), r.pairs.end());
  model_found.combine_each([&](const ModelFound& m) {
    r.model_pairs.insert(r.model_pairs.end(), m.pairs.begin(), m.pairs.end());
    r.model_tests += m.tests;
    r.model_lps += m.lps;
  });
  std::sort(r.model_pairs.begin(), r.model_pairs.end(),
            [](const auto& x, const auto& y) { return x.cells < y.cells; });
  r.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

CellOverlapReport check_overlapping_cells(const CellMesh& mesh, const MeshFaces& faces,
                                          OverlapSearch search) {
  const auto t0 = Clock::now();
  CellOverlapReport r;
  if (search == OverlapSearch::Fast) {
    r.certificate = certify_cells_disjoint(mesh, faces);
    if (r.certificate.result == OverlapCertificate::Clean) {
      r.method = "boundary";
      r.total_seconds = since(t0);
      return r;
    }
  }
  CellOverlapReport full = find_overlapping_cells(mesh);
  full.certificate = r.certificate;
  full.method = "exhaustive";
  full.total_seconds = since(t0);
  return full;
}

double model_pair_thickness(const CellOverlapReport& r, std::pair<int32_t, int32_t> cells) {
  const auto it = std::lower_bound(r.model_pairs.begin(), r.model_pairs.end(), cells,
                                   [](const auto& m, const auto& c) { return m.cells < c; });
  return it != r.model_pairs.end() && it->cells == cells ? it->thickness : -1.0;
}

std::string describe_overlap(const std::string& source, const CellOverlapReport& r, const CellMesh* mesh) {
  if (r.pairs.empty()) return source + ": no interpenetrating cells";
  const auto [a, b] = r.pairs.front();
  const std::string cells = source + ": cells " + std::to_string(a) + " and " + std::to_string(b);
  const double thick = model_pair_thickness(r, r.pairs.front());
  if (thick >= 0) {
    char by[64];
    std::snprintf(by, sizeof by, "%.2g", thick);
    const std::string cause = mesh ? warped_quad_cause(*mesh, a, b) : std::string();
    return cells + " overlap by " + by + " as the oracle models them (" + std::to_string(r.pairs.size()) +
           " overlapping pairs): " +
           (cause.empty() ? std::string("their quads are not planar and the oracle takes each quad as one plane")
                          : cause);
  }
  return cells + " interpenetrate (" + std::to_string(r.pairs.size()) +
         " such pairs): the input has no visibility order";
}

}  // namespace vob

