// The exhaustive overlap search of cell_overlap.h (every candidate pair from CGAL's box
// self-intersection, decided exactly), and the default check that tries the boundary
// certificate first.
#include <algorithm>
#include <chrono>
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
  std::vector<CellBox> boxes;
  boxes.reserve(nc);
  for (size_t c = 0; c < nc; ++c) {
    const int32_t* ids = mesh.cell_points(c);
    CGAL::Bbox_3 bb;
    for (int i = 0; i < mesh.cell_size(c); ++i) {
      const Vec3& p = mesh.points[ids[i]];
      bb += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
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
                            if (cells_interpenetrate(mesh, a, b))
                              out.emplace_back(std::min(a, b), std::max(a, b));
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

std::string describe_overlap(const std::string& source, const CellOverlapReport& r) {
  if (r.pairs.empty()) return source + ": no interpenetrating cells";
  const auto [a, b] = r.pairs.front();
  return source + ": cells " + std::to_string(a) + " and " + std::to_string(b) +
         " interpenetrate (" + std::to_string(r.pairs.size()) +
         " such pairs): the input has no visibility order";
}

}  // namespace vob

