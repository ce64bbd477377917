#include "algorithms/havs/face_bins.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace vob::havs {

namespace {

constexpr size_t kChunk = 8192;  // faces per binning task; chunks keep the drawing order

// The sample centres a face with projected points q[0..n) may cover: the range that
// PolygonRaster::setup's rejection test (may_cover_a_sample) uses, with its margin; the whole
// frame when a point is not in front of the eye (the projection then says nothing).
SampleRect reach(const SampleFrame& frame, const ProjectedVertex* q, int n) {
  // min / max as selects (the compares of points at random were mispredicted branches).
  double lx = q[0].x, hx = q[0].x, ly = q[0].y, hy = q[0].y;
  bool front = q[0].in_front;
  for (int i = 1; i < n; ++i) {
    front &= q[i].in_front;
    lx = q[i].x < lx ? q[i].x : lx;
    hx = q[i].x > hx ? q[i].x : hx;
    ly = q[i].y < ly ? q[i].y : ly;
    hy = q[i].y > hy ? q[i].y : hy;
  }
  if (!front) return frame.bounds();
  double m = 1e-6 * (1.0 + std::max({std::fabs(lx), std::fabs(hx), std::fabs(ly), std::fabs(hy)}));
  // gl rule: snapping moves a vertex by up to 1/512 pixel, so the covered centres reach that
  // far beyond the exact projection.
  if (frame.rule() == RasterRule::gl) m += 1.0 / 128;
  const double x0 = std::ceil(lx - m - 0.5), x1 = std::floor(hx + m - 0.5);
  const double y0 = std::ceil(ly - m - 0.5), y1 = std::floor(hy + m - 0.5);
  if (!(x0 <= x1 && y0 <= y1 && x1 >= 0 && y1 >= 0 && x0 < frame.cols() && y0 < frame.rows()))
    return {};
  return SampleRect{int(std::max(x0, 0.0)), int(std::max(y0, 0.0)),
                    int(std::min(x1, frame.cols() - 1.0)), int(std::min(y1, frame.rows() - 1.0))};
}

}  // namespace

void bin_faces(const FaceData& fd, const SampleFrame& frame, const std::vector<int32_t>& order, FaceBins& b,
               int rows_per_band) {
  b.rows_per_band = rows_per_band;
  b.bands = (frame.rows() + b.rows_per_band - 1) / b.rows_per_band;
  const std::vector<Vec3>& pts = fd.scene.mesh().points;
  b.projected.resize(pts.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pts.size(), 4096), [&](const auto& r) {
    frame.project_all(pts.data() + r.begin(), r.size(), b.projected.data() + r.begin());
  });
  if (!frame.ortho()) {
    b.inv_len.resize(frame.num_samples());
    b.len.resize(frame.num_samples());
    tbb::parallel_for(0, frame.rows(), [&](int sy) {
      for (int sx = 0; sx < frame.cols(); ++sx) {
        const double l = length(frame.x(sx, sy));  // PolygonRaster's |X|, bit for bit
        b.len[frame.index(sx, sy)] = l;
        b.inv_len[frame.index(sx, sy)] = 1.0 / l;
      }
    });
  }
  // Two passes over chunks of the drawing order: make each face's item (position order) and
  // count per (chunk, band), then copy the items to their bands; the slots are band-major,
  // chunk-minor, so every band's list keeps the drawing order. The first pass does the
  // scattered reads (faces come in depth order), the second reads sequentially.
  const size_t n = order.size(), chunks = (n + kChunk - 1) / kChunk, nb = size_t(b.bands);
  std::vector<BandItem>& made = b.made;
  std::vector<int64_t>& slot = b.slot;
  made.resize(n);
  slot.assign(chunks * nb, 0);
  const FaceData::Points* fp = fd.points.data();
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    int64_t* cnt = &slot[c * nb];
    ProjectedVertex q[4];
    for (size_t i = c * kChunk, e = std::min(n, i + kChunk); i < e; ++i) {
      if (i + 16 < e) __builtin_prefetch(&fp[order[i + 16]]), __builtin_prefetch(&fd.boundary[order[i + 16]]);
      const int32_t f = order[i];
      const FaceData::Points& ids = fp[f];
      const int m = ids.id[3] < 0 ? 3 : 4;
      for (int j = 0; j < m; ++j) q[j] = b.projected[ids.id[j]];
      BandItem& item = made[i];
      item.tag = f * 2 + fd.boundary[f];
      for (int j = 0; j < 4; ++j) item.ids[j] = ids.id[j];
      if (m == 3) item.ids[3] = q[0].in_front && q[1].in_front && q[2].in_front ? kFrontTriangle : kTriangle;
      item.rect = reach(frame, q, m);
      const SampleRect& r = item.rect;
      if (!r.empty())
        for (int band = r.y0 / b.rows_per_band; band <= r.y1 / b.rows_per_band; ++band) ++cnt[band];
    }
  });
  b.start.assign(nb + 1, 0);
  int64_t sum = 0;
  for (size_t band = 0; band < nb; ++band) {
    b.start[band] = sum;
    for (size_t c = 0; c < chunks; ++c) {
      const int64_t k = slot[c * nb + band];
      slot[c * nb + band] = sum;
      sum += k;
    }
  }
  b.start[nb] = sum;
  b.items.resize(sum);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    int64_t* next = &slot[c * nb];
    for (size_t i = c * kChunk, e = std::min(n, i + kChunk); i < e; ++i) {
      const SampleRect& r = made[i].rect;
      if (r.empty()) continue;
      for (int band = r.y0 / b.rows_per_band; band <= r.y1 / b.rows_per_band; ++band) b.items[next[band]++] = made[i];
    }
  });
}

}  // namespace vob::havs
