#include "harness/oracle/sequences.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "harness/geometry/polygon_plane.h"
#include "harness/raster/fragments.h"
#include "harness/scene/input_error.h"

namespace vob {

CellSequences make_cell_sequences(int cols, int rows, int supersample,
                                  std::vector<std::vector<RaySegment>>&& seg,
                                  std::vector<std::vector<int32_t>>&& counts) {
  CellSequences cs;
  cs.cols = cols;
  cs.rows = rows;
  cs.supersample = supersample;
  cs.offsets.assign(cs.num_samples() + 1, 0);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) cs.offsets[int64_t(y) * cols + x + 1] = counts[y][x];
  for (int64_t i = 0; i < cs.num_samples(); ++i) cs.offsets[i + 1] += cs.offsets[i];
  cs.segments.resize(cs.offsets.back());
  tbb::parallel_for(0, rows, [&](int y) {
    std::copy(seg[y].begin(), seg[y].end(), cs.segments.begin() + cs.offsets[int64_t(y) * cols]);
    std::vector<RaySegment>().swap(seg[y]);
    for (int x = 0; x < cols; ++x) {
      const int64_t i = int64_t(y) * cols + x;
      std::sort(cs.segments.begin() + cs.offsets[i], cs.segments.begin() + cs.offsets[i + 1],
                [](const RaySegment& a, const RaySegment& b) {
                  return a.mid() != b.mid() ? a.mid() < b.mid() : a.cell < b.cell;
                });
    }
  });
  return cs;
}

CellSequences raster_cell_sequences(const Scene& scene, const Camera& view, int supersample,
                                    double min_length) {
  if (scene.kind() != SceneKind::Cells)
    throw InputError("oracle", "cell sequences", "scene '" + scene.name() + "' has no cells");
  CollectOptions co;
  co.supersample = supersample;
  const FragmentCollector fc(scene, view, all_primitives(scene), co);
  const int cols = fc.frame().cols(), rows = fc.frame().rows();
  std::vector<std::vector<RaySegment>> seg(rows);
  std::vector<std::vector<int32_t>> counts(rows, std::vector<int32_t>(cols, 0));
  tbb::enumerable_thread_specific<FragmentLists> lists;
  tbb::parallel_for(0, fc.num_bands(), [&](int b) {
    FragmentLists& fl = lists.local();
    fc.collect_band(b, fl);
    for (int y = fl.row0; y < fl.row1; ++y)
      for (int x = 0; x < cols; ++x)
        for (const Fragment& f : fl.at(x, y))
          if (f.t_out - f.t_in > min_length) {
            seg[y].push_back({f.prim, f.t_in, f.t_out});
            ++counts[y][x];
          }
  });
  return make_cell_sequences(cols, rows, supersample, std::move(seg), std::move(counts));
}

nlohmann::json SequenceComparison::to_json() const {
  return {{"samples", samples}, {"equal", equal}, {"grazing", grazing}, {"in_plane", in_plane},
          {"mismatched", mismatched}, {"examples", examples}};
}

namespace {

std::vector<int32_t> cells_at_least(std::span<const RaySegment> s, double len) {
  std::vector<int32_t> v;
  for (const RaySegment& r : s)
    if (r.length() >= len) v.push_back(r.cell);
  return v;
}

nlohmann::json describe(std::span<const RaySegment> s) {
  nlohmann::json j = nlohmann::json::array();
  for (const RaySegment& r : s) j.push_back({r.cell, r.t_in, r.t_out});
  return j;
}

// Differences of a and b explained by segments close to tol (see sequences.h).
bool grazing_only(std::span<const RaySegment> a, std::span<const RaySegment> b, double tol) {
  std::map<int32_t, std::pair<double, double>> len;  // cell -> (length in a, length in b)
  for (const RaySegment& r : a) len[r.cell].first = r.length();
  for (const RaySegment& r : b) len[r.cell].second = r.length();
  for (const auto& [cell, l] : len) {
    const double hi = std::max(l.first, l.second), lo = std::min(l.first, l.second);
    if (hi >= 4 * tol && lo < tol / 4) return false;
  }
  auto common = [&](std::span<const RaySegment> s) {
    std::vector<int32_t> v;
    for (const RaySegment& r : s) {
      const auto& l = len[r.cell];
      if (l.first >= tol && l.second >= tol) v.push_back(r.cell);
    }
    return v;
  };
  return common(a) == common(b);
}

// Differences of a and b all explained by cells whose face plane holds the sample's ray:
// with those cells removed, the sequences agree.
bool in_plane_only(int64_t sample, std::span<const RaySegment> a, std::span<const RaySegment> b,
                   double tol, const InFacePlane& in_plane) {
  auto keep = [&](std::span<const RaySegment> s) {
    std::vector<int32_t> v;
    for (const RaySegment& r : s)
      if (r.length() >= tol && !in_plane(sample, r.cell)) v.push_back(r.cell);
    return v;
  };
  return keep(a) == keep(b);
}

}  // namespace

InFacePlane ray_in_face_plane_test(const Scene& scene, const Camera& view, int supersample,
                                   double tol) {
  auto frame = std::make_shared<SampleFrame>(view, supersample);
  return [&scene, frame, tol](int64_t sample, int32_t cell) {
    const CellMesh& m = scene.mesh();
    const Ray ray = frame->ray(int(sample % frame->cols()), int(sample / frame->cols()));
    const LocalFaces& lf = cell_local_faces(m.types[cell]);
    const int32_t* p = m.cell_points(cell);
    for (int f = 0; f < lf.count; ++f) {
      Vec3 pts[4];
      for (int i = 0; i < lf.size[f]; ++i) pts[i] = m.points[p[lf.v[f][i]]];
      const PolygonPlane plane = newell_plane(pts, lf.size[f]);
      const Vec3 n = normalize(plane.normal);
      if (std::fabs(dot(n, ray.dir)) < 1e-9 && std::fabs(dot(n, ray.origin - plane.centroid)) < tol)
        return true;
    }
    return false;
  };
}

SequenceComparison compare_sequences(const CellSequences& a, const CellSequences& b, double tol,
                                     int max_examples, const InFacePlane& in_plane) {
  if (a.cols != b.cols || a.rows != b.rows)
    throw InputError("oracle", "cell sequences",
                     "grids differ: " + std::to_string(a.cols) + "x" + std::to_string(a.rows) +
                         " vs " + std::to_string(b.cols) + "x" + std::to_string(b.rows));
  SequenceComparison c;
  c.samples = a.num_samples();
  for (int64_t i = 0; i < c.samples; ++i) {
    const auto sa = a.at(i), sb = b.at(i);
    if (cells_at_least(sa, tol) == cells_at_least(sb, tol)) {
      ++c.equal;
    } else if (grazing_only(sa, sb, tol)) {
      ++c.grazing;
    } else if (in_plane && in_plane_only(i, sa, sb, tol, in_plane)) {
      ++c.in_plane;
    } else {
      ++c.mismatched;
      if (int(c.examples.size()) < max_examples)
        c.examples.push_back({{"sample", {i % a.cols, i / a.cols}},
                              {"a", describe(sa)},
                              {"b", describe(sb)}});
    }
  }
  return c;
}

}  // namespace vob
