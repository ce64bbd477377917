#include "harness/raster/fragments.h"

#include <numeric>
#include <optional>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "harness/raster/cell_raster_gl.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/splat.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
struct Record {
  int64_t local;
  Fragment f;
};
}  // namespace

// Receives the fragments of one primitive within one band.
class FragmentSink {
 public:
  FragmentSink(std::vector<Record>& recs, int row0, int cols) : recs_(recs), row0_(row0), cols_(cols) {}
  void begin(int32_t prim, int32_t pos) { prim_ = prim, pos_ = pos; }
  void add(int sx, int sy, double t0, double t1) {
    recs_.push_back({int64_t(sy - row0_) * cols_ + sx, {t0, t1, prim_, pos_}});
  }

 private:
  std::vector<Record>& recs_;
  int row0_, cols_;
  int32_t prim_ = 0, pos_ = 0;
};

FragmentCollector::FragmentCollector(const Scene& scene, const Camera& view,
                                     const std::vector<int32_t>& order, const CollectOptions& opt)
    : scene_(scene), order_(order), frame_(view, opt.supersample, opt.raster) {
  if (opt.raster == RasterRule::gl)  // GL's near and far planes about the scene (raster_rule.h)
    frame_.set_gl_depth_range(gl_depth_range(view, scene.bounds().center(), scene.bounds().radius()));
  if (opt.raster == RasterRule::gl && scene.kind() == SceneKind::Voxels)
    throw InputError("--raster gl", std::string(scene_kind_name(scene.kind())),
                     "the gl sampling rule covers triangle and cell scenes");
  if (opt.splat_radius_px < 0 || !std::isfinite(opt.splat_radius_px))
    throw InputError("oracle", "splat radius", "must be a finite number >= 0");
  splat_radius_px_ = opt.splat_radius_px;
  const int64_t n = scene.kind() == SceneKind::Voxels ? int64_t(scene.grid().num_voxels())
                                                        : int64_t(scene.num_primitives());
  for (size_t i = 0; i < order_.size(); ++i) {
    const int32_t id = order_[i];
    if (id < 0 || id >= n)
      throw InputError("order", "position " + std::to_string(i),
                       "primitive id " + std::to_string(id) + " is not in [0, " +
                           std::to_string(n) + ")");
    if (scene.kind() == SceneKind::Voxels && !scene.grid().significant(id))
      throw InputError("order", "position " + std::to_string(i),
                       "voxel " + std::to_string(id) + " is not significant (value <= threshold)");
  }
  if (scene.kind() == SceneKind::Cells) min_segment_ = oracle_min_segment(scene.bounds(), view);
  if (scene.kind() == SceneKind::Cells) projected_ = project_points(frame_, scene.mesh().points);

  // Bounds of every primitive, then the band lists in drawing order.
  box_.resize(order_.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, order_.size(), 1024),
                    [&](const tbb::blocked_range<size_t>& r) {
    std::optional<CellClipper> clip;
    std::optional<GlCellRaster> gl_cells;
    if (scene_.kind() == SceneKind::Cells) clip.emplace(frame_, scene_.mesh(), projected_, min_segment_);
    if (scene_.kind() == SceneKind::Cells && frame_.rule() == RasterRule::gl)
      gl_cells.emplace(frame_, scene_.mesh(), projected_, min_segment_);
    for (size_t i = r.begin(); i < r.end(); ++i) {
      const int32_t id = order_[i];
      SampleRect b;
      switch (scene_.kind()) {
        case SceneKind::Cells: b = gl_cells ? gl_cells->bounds(id) : clip->bounds(id); break;
        case SceneKind::Triangles: {
          const TriangleSoup& s = scene_.soup();
          const Vec3 v[3] = {s.points[s.tris[id][0]], s.points[s.tris[id][1]], s.points[s.tris[id][2]]};
          PolygonRaster pr;
          if (pr.setup(frame_, v, 3)) b = pr.bounds();
          break;
        }
        case SceneKind::Voxels: {
          const VoxelGrid& g = scene_.grid();
          Splat sp;
          if (make_splat(frame_, g.centre_of(id), g.spacing, splat_radius_px_, sp)) b = sp.box;
          break;
        }
      }
      box_[i] = b;
    }
  });
  band_rows_ = opt.band_rows > 0 ? opt.band_rows : std::max(1, 8192 / frame_.cols());
  const int nb = (frame_.rows() + band_rows_ - 1) / band_rows_;
  band_start_.assign(nb + 1, 0);
  for (const SampleRect& b : box_)
    if (!b.empty())
      for (int k = b.y0 / band_rows_; k <= b.y1 / band_rows_; ++k) ++band_start_[k + 1];
  std::partial_sum(band_start_.begin(), band_start_.end(), band_start_.begin());
  band_items_.resize(band_start_[nb]);
  std::vector<int64_t> cursor(band_start_.begin(), band_start_.end() - 1);
  for (size_t i = 0; i < box_.size(); ++i) {
    const SampleRect& b = box_[i];
    if (!b.empty())
      for (int k = b.y0 / band_rows_; k <= b.y1 / band_rows_; ++k)
        band_items_[cursor[k]++] = static_cast<int32_t>(i);
  }
}

void FragmentCollector::emit_primitive(int32_t pos, const SampleRect& clip, FragmentSink& sink) const {
  const int32_t id = order_[pos];
  sink.begin(id, pos);
  switch (scene_.kind()) {
    case SceneKind::Cells: {
      if (frame_.rule() == RasterRule::gl) {  // faces under llvmpipe's rule (cell_raster_gl.h)
        GlCellRaster gc(frame_, scene_.mesh(), projected_, min_segment_);
        gc.scan(id, clip, [&](int sx, int sy, double t0, double t1) { sink.add(sx, sy, t0, t1); });
        break;
      }
      CellClipper cc(frame_, scene_.mesh(), projected_, min_segment_);
      cc.setup(id);
      cc.scan(clip, [&](int sx, int sy, double t0, double t1) { sink.add(sx, sy, t0, t1); });
      break;
    }
    case SceneKind::Triangles: {
      const TriangleSoup& s = scene_.soup();
      const Vec3 v[3] = {s.points[s.tris[id][0]], s.points[s.tris[id][1]], s.points[s.tris[id][2]]};
      const bool gl = frame_.rule() == RasterRule::gl;
      rasterize_polygon(frame_, v, 3, clip, [&](int sx, int sy, double t, int64_t depth24) {
        sink.add(sx, sy, t, gl ? double(depth24) : t);
      });
      break;
    }
    case SceneKind::Voxels: {
      const VoxelGrid& g = scene_.grid();
      Splat sp;
      if (make_splat(frame_, g.centre_of(id), g.spacing, splat_radius_px_, sp))
        scan_splat(sp, clip, [&](int sx, int sy, double) { sink.add(sx, sy, sp.depth, sp.depth); });
      break;
    }
  }
}

void FragmentCollector::collect_band(int b, FragmentLists& out) const {
  out.cols = frame_.cols();
  out.row0 = band_row0(b);
  out.row1 = band_row1(b);
  // Records of one band, kept per thread to avoid reallocating for every band.
  thread_local std::vector<Record> recs;
  recs.clear();
  FragmentSink sink(recs, out.row0, out.cols);
  const SampleRect band{0, out.row0, out.cols - 1, out.row1 - 1};
  for (int64_t k = band_start_[b]; k < band_start_[b + 1]; ++k) {
    const int32_t pos = band_items_[k];
    emit_primitive(pos, box_[pos].intersect(band), sink);
  }
  // Stable counting sort by sample: drawing order is kept within each sample.
  const int64_t n = out.num_samples();
  out.offsets.assign(n + 1, 0);
  for (const Record& r : recs) ++out.offsets[r.local + 1];
  std::partial_sum(out.offsets.begin(), out.offsets.end(), out.offsets.begin());
  out.fragments.resize(recs.size());
  for (const Record& r : recs) out.fragments[out.offsets[r.local]++] = r.f;
  for (int64_t i = n; i > 0; --i) out.offsets[i] = out.offsets[i - 1];
  out.offsets[0] = 0;
}

FragmentLists FragmentCollector::collect_all() const {
  const int nb = num_bands();
  std::vector<FragmentLists> bands(nb);
  tbb::parallel_for(0, nb, [&](int b) { collect_band(b, bands[b]); });
  FragmentLists all;
  all.cols = frame_.cols();
  all.row0 = 0;
  all.row1 = frame_.rows();
  int64_t total = 0;
  for (const FragmentLists& b : bands) total += int64_t(b.fragments.size());
  all.offsets.reserve(all.num_samples() + 1);
  all.offsets.push_back(0);
  all.fragments.reserve(total);
  for (FragmentLists& b : bands) {
    const int64_t base = int64_t(all.fragments.size());
    for (int64_t i = 1; i <= b.num_samples(); ++i) all.offsets.push_back(base + b.offsets[i]);
    all.fragments.insert(all.fragments.end(), b.fragments.begin(), b.fragments.end());
    b = FragmentLists{};
  }
  return all;
}

size_t FragmentCollector::bytes() const {
  return order_.capacity() * sizeof(int32_t) + box_.capacity() * sizeof(SampleRect) +
         band_start_.capacity() * sizeof(int64_t) + band_items_.capacity() * sizeof(int32_t) +
         (projected_.x.capacity() + projected_.y.capacity() + projected_.zc.capacity()) * sizeof(double);
}

FragmentLists collect_fragments(const Scene& scene, const Camera& view,
                                const std::vector<int32_t>& order, const CollectOptions& opt) {
  return FragmentCollector(scene, view, order, opt).collect_all();
}

std::vector<int32_t> all_primitives(const Scene& scene) {
  // Not through the scene cache: the oracle must not count as an orderer asking for it.
  if (scene.kind() == SceneKind::Voxels) return significant_voxels(scene.grid());
  std::vector<int32_t> ids(scene.num_primitives());
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

}  // namespace vob
