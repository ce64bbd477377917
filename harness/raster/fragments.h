// The fragment collector: for a scene, a view, a drawing order and S, every fragment of
// every sample, grouped per sample in drawing order (a stable counting sort by sample,
// stored in CSR form). Cells give ray segments (cell_clip.h), triangles hit depths
// (polygon_raster.h), voxels splats (splat.h).
//
// The image is cut into bands of sample rows; each primitive is listed in the bands its
// bounds touch, and a band is collected independently of the others (thread-safe), so the
// oracle and the compositor work band by band in parallel with bounded memory.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "harness/raster/cell_clip.h"
#include "harness/raster/sample_frame.h"
#include "harness/scene/scene.h"

namespace vob {

struct Fragment {
  // Cells: the ray segment. Triangles and voxels: t_in the hit depth; t_out the same, except
  // for triangles under the gl rule: the 24-bit depth llvmpipe's depth test compares there
  // (llvmpipe_depth.h), which is what the oracle compares under that rule.
  double t_in = 0, t_out = 0;
  int32_t prim = 0;            // cell, triangle or voxel id
  int32_t pos = 0;             // position of prim in the drawing order
  double mid() const { return 0.5 * (t_in + t_out); }
};

// Fragments of the samples in rows [row0, row1) of the frame's grid.
struct FragmentLists {
  int cols = 0, row0 = 0, row1 = 0;
  std::vector<int64_t> offsets;  // size samples + 1, by local index (sy - row0) * cols + sx
  std::vector<Fragment> fragments;

  int64_t num_samples() const { return int64_t(row1 - row0) * cols; }
  std::span<const Fragment> local(int64_t i) const {
    return {fragments.data() + offsets[i], fragments.data() + offsets[i + 1]};
  }
  std::span<const Fragment> at(int sx, int sy) const { return local(int64_t(sy - row0) * cols + sx); }
  size_t bytes() const {
    return offsets.capacity() * sizeof(int64_t) + fragments.capacity() * sizeof(Fragment);
  }
};

struct CollectOptions {
  int supersample = 1;         // S x S samples per pixel
  double splat_radius_px = 0;  // voxels: footprint radius in pixels; 0 = projected voxel size
  int band_rows = 0;           // rows per band; 0 = about 8192 samples per band
  RasterRule raster = RasterRule::exact;  // gl: llvmpipe's coverage (raster_rule.h; cells: cell_raster_gl.h)
};

class FragmentCollector {
 public:
  // Validates the order: every id must name a primitive of the scene (voxels: a significant
  // voxel), else InputError naming its position. Ids may be missing (not drawn).
  FragmentCollector(const Scene& scene, const Camera& view, const std::vector<int32_t>& order,
                    const CollectOptions& opt = {});

  const SampleFrame& frame() const { return frame_; }
  const Scene& scene() const { return scene_; }
  const std::vector<int32_t>& order() const { return order_; }
  double min_segment() const { return min_segment_; }  // cells: shorter segments are dropped
  double splat_radius_px() const { return splat_radius_px_; }

  int num_bands() const { return static_cast<int>(band_start_.size()) - 1; }
  int band_row0(int b) const { return b * band_rows_; }
  int band_row1(int b) const { return std::min(frame_.rows(), (b + 1) * band_rows_); }
  // Collects band b (reusing out's storage). Safe to call concurrently for different outs.
  void collect_band(int b, FragmentLists& out) const;
  // All samples, bands collected in parallel.
  FragmentLists collect_all() const;
  size_t bytes() const;  // bounds, band lists and projected points

 private:
  void emit_primitive(int32_t pos, const SampleRect& clip, class FragmentSink& sink) const;

  Scene scene_;
  std::vector<int32_t> order_;
  SampleFrame frame_;
  double min_segment_ = 0, splat_radius_px_ = 0;
  ProjectedPoints projected_;          // cells: every mesh point
  std::vector<SampleRect> box_;        // per order position
  int band_rows_ = 1;
  std::vector<int64_t> band_start_;    // CSR of order positions per band
  std::vector<int32_t> band_items_;
};

// Convenience: all fragments of the view in one CSR (rows [0, rows)).
FragmentLists collect_fragments(const Scene& scene, const Camera& view,
                                const std::vector<int32_t>& order, const CollectOptions& opt = {});

// The identity drawing order of a scene: every primitive id (voxels: the significant ones).
std::vector<int32_t> all_primitives(const Scene& scene);

}  // namespace vob
