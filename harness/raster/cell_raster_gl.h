// Cell fragments under the gl sampling rule (raster_rule.h): what a GL renderer that
// rasterizes a cell's faces draws. Every face of the cell is rasterized with llvmpipe's
// coverage on the snapped window coordinates (PolygonRaster under RasterRule::gl: the
// fill rule, the quad split, the depth plane through the snapped vertices), and at each
// pixel centre the cell's segment runs from the nearest to the farthest depth of the faces
// that cover it. The snapped faces of a cell form a closed surface and the fill rule gives
// an edge to exactly one of two faces on opposite sides of it (to both or neither at a
// fold), so a covered pixel has as many faces of one screen orientation as of the other:
// at least two; a pixel with fewer is a grazing fold and gives no segment. Segments not
// longer than min_length are dropped, as in cell_clip.h.
//
// Face neighbours share snapped vertices, so they cover the same pixels of their common
// face with the same plane: their segments meet (up to the rounding of the plane's
// coefficients, far below kOverlapRelative). Depths stay doubles: compositing cells
// involves no depth test; the 24-bit depth is the layer backends' business.
#pragma once
#include <cstdint>
#include <vector>

#include "harness/raster/cell_clip.h"
#include "harness/scene/cell_mesh.h"

namespace vob {

class GlCellRaster {
 public:
  GlCellRaster(const SampleFrame& frame, const CellMesh& mesh, const ProjectedPoints& projected,
               double min_length)
      : frame_(frame), mesh_(mesh), proj_(projected), min_length_(min_length) {}
  // The pixels cell c may cover (the union of its faces' llvmpipe bounding boxes).
  SampleRect bounds(int32_t c) const;
  // Calls emit(sx, sy, t_in, t_out) for every pixel of `clip` where cell c has a segment.
  template <class Emit>
  void scan(int32_t c, const SampleRect& clip, Emit&& emit);

 private:
  // Rasterizes every face of c into lo_, hi_, n_ over rect r (r non-empty).
  void accumulate(int32_t c, const SampleRect& r);
  // Calls fn(PolygonRaster&) for every face of c that sets up under the frame's rule.
  template <class Fn>
  void each_face(int32_t c, Fn&& fn) const;

  const SampleFrame& frame_;
  const CellMesh& mesh_;
  const ProjectedPoints& proj_;
  double min_length_;
  std::vector<double> lo_, hi_;
  std::vector<uint8_t> n_;
};

template <class Emit>
void GlCellRaster::scan(int32_t c, const SampleRect& clip, Emit&& emit) {
  const SampleRect r = bounds(c).intersect(clip);
  if (r.empty()) return;
  accumulate(c, r);
  const int w = r.x1 - r.x0 + 1;
  for (int sy = r.y0; sy <= r.y1; ++sy)
    for (int sx = r.x0; sx <= r.x1; ++sx) {
      const size_t i = size_t(sy - r.y0) * w + (sx - r.x0);
      if (n_[i] >= 2 && hi_[i] - lo_[i] > min_length_) emit(sx, sy, lo_[i], hi_[i]);
    }
}

}  // namespace vob
