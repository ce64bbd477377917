#include "algorithms/havs/havs_frame.h"

#include "algorithms/havs/face_bins.h"

#include <algorithm>
#include <numeric>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>

#include "harness/cpu_features.h"
#include "harness/oracle/k_metric.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"
#include "harness/scene/input_error.h"
#include "harness/sort/radix_sort.h"

namespace vob::havs {

namespace {

FaceData::Linear triangle_fn(const Vec3& p0, const Vec3& p1, const Vec3& p2, double s0, double s1,
                             double s2) {
  const Vec3 n = cross(p1 - p0, p2 - p0);
  const double nn = dot(n, n);
  if (!(nn > 0)) return {Vec3{}, (s0 + s1 + s2) / 3};
  // Gradient of the barycentric coordinate of p_i: n x (opposite edge) / |n|^2.
  const Vec3 g = (cross(n, p2 - p1) * s0 + cross(n, p0 - p2) * s1 + cross(n, p1 - p0) * s2) / nn;
  return {g, s0 - dot(g, p0)};
}

void store_pixel(Image& img, int64_t pixel, const PixelAccum& a) {
  img.rgb[3 * pixel] = a.r;
  img.rgb[3 * pixel + 1] = a.g;
  img.rgb[3 * pixel + 2] = a.b;
}

void check_k(int k) {
  if (k < 1 || k > kMaxK) throw InputError("havs", "k", "must be in [1, " + std::to_string(kMaxK) + "]");
}

}  // namespace

size_t FaceData::bytes() const {
  return boundary.capacity() + points.capacity() * sizeof(Points) + scalar.capacity() * sizeof(Linear) + quad_slot.capacity() * 4 +
         (quad_half2.capacity() + quad_split.capacity()) * sizeof(Linear);
}

FaceData build_face_data(const Scene& scene) {
  FaceData fd;
  fd.scene = scene;
  fd.faces = &scene.faces();
  fd.centroids = &scene.face_centroids();
  const CellMesh& m = scene.mesh();
  const MeshFaces& mf = *fd.faces;
  double lo = 0, hi = 0;
  if (!m.scalars.empty()) {
    lo = *std::min_element(m.scalars.begin(), m.scalars.end());
    hi = *std::max_element(m.scalars.begin(), m.scalars.end());
  }
  const auto norm = [&](int32_t p) { return hi > lo ? (m.scalar(p) - lo) / (hi - lo) : 0.5; };
  const size_t nf = mf.num_faces();
  fd.boundary.resize(nf);
  fd.points.resize(nf);
  fd.scalar.resize(nf);
  fd.quad_slot.assign(nf, -1);
  for (size_t f = 0; f < nf; ++f) {
    fd.boundary[f] = mf.cell1[f] < 0;
    const int32_t* id = mf.face_points(f);
    for (int j = 0; j < 4; ++j) fd.points[f].id[j] = j < mf.face_size(f) ? id[j] : -1;
    const Vec3 &p0 = m.points[id[0]], &p1 = m.points[id[1]], &p2 = m.points[id[2]];
    fd.scalar[f] = triangle_fn(p0, p1, p2, norm(id[0]), norm(id[1]), norm(id[2]));
    if (mf.face_size(f) == 4) {
      const Vec3& p3 = m.points[id[3]];
      fd.quad_slot[f] = static_cast<int32_t>(fd.quad_half2.size());
      fd.quad_half2.push_back(triangle_fn(p0, p2, p3, norm(id[0]), norm(id[2]), norm(id[3])));
      const Vec3 n = cross(p2 - p0, p1 - p0) + cross(p3 - p0, p2 - p0);
      Vec3 side = cross(n, p2 - p0);
      if (dot(side, p3 - p0) < 0) side = -side;
      fd.quad_split.push_back({side, -dot(side, p0)});
    }
  }
  fd.tau0 = 2.4 / std::max(scene.bounds().radius(), 1e-300);  // as render/compositor.cpp
  return fd;
}

void sort_faces(const FaceData& fd, const Camera& view, SortBuffers& buf, std::vector<int32_t>& order) {
  const Vec3* c = fd.centroids->points.data();
  const size_t n = fd.centroids->points.size();
  order.resize(n);
  const Vec3 eye = view.eye, f = view.forward();
  if (view.ortho)
    buf.sort.sort(n, [=](size_t i) { return float_sort_key(static_cast<float>(dot(c[i] - eye, f))); }, order.data());
  else
    buf.sort.sort(n, [=](size_t i) { return float_sort_key(static_cast<float>(length(c[i] - eye))); }, order.data());
}

std::vector<int32_t> cell_order_from_faces(const FaceData& fd, const std::vector<int32_t>& face_order) {
  const MeshFaces& mf = *fd.faces;
  const size_t nf = face_order.size(), nc = fd.scene.mesh().num_cells();
  std::vector<int32_t> rank(nf);
  for (size_t i = 0; i < nf; ++i) rank[face_order[i]] = static_cast<int32_t>(i);
  // Counting sort of cells by the rank of their last face, descending.
  std::vector<int32_t> key(nc, 0), count(nf + 1, 0);
  for (size_t c = 0; c < nc; ++c) {
    int32_t r = 0;
    for (int32_t i = mf.cell_face_offsets[c]; i < mf.cell_face_offsets[c + 1]; ++i)
      r = std::max(r, rank[mf.cell_faces[i]]);
    key[c] = static_cast<int32_t>(nf - 1) - r;
    ++count[key[c] + 1];
  }
  std::partial_sum(count.begin(), count.end(), count.begin());
  std::vector<int32_t> out(nc);
  for (size_t c = 0; c < nc; ++c) out[count[key[c]]++] = static_cast<int32_t>(c);
  return out;
}

namespace {

// k = 2, the paper's case: each pixel's two entries kept sorted (e0 nearer), as one record
// with its accumulator (one cache line per fragment). An entry is a 64-bit key, the float
// bits of d (d >= 0, -0 made +0, so the bits order as the values) over the tag, so key
// order is `nearer` exactly, and the insert is branch-free selects instead of the data-
// dependent branches that mispredicted about once per fragment. Which two entries stay and
// which pair is composited depends only on the set of three, so the segments are
// kbuffer_insert's (the unsorted hardware layout) exactly; the analysis reruns that one.
struct Pair2 {
  uint64_t k0, k1;
  float v0, v1;
  PixelAccum acc;
  uint8_t count;
};

inline uint64_t key_of(const KEntry& e) {
  const float d = e.d + 0.f;  // -0 -> +0
  uint32_t bits;
  __builtin_memcpy(&bits, &d, 4);
  return (uint64_t(bits) << 32) | uint32_t(e.tag);
}
inline float d_of(uint64_t key) {
  const uint32_t bits = uint32_t(key >> 32);
  float d;
  __builtin_memcpy(&d, &bits, 4);
  return d;
}

// The segments of a band in the order the k-buffer emits them, shaded in batches: the
// opacities (one exp each) in a loop the compiler vectorises, then each pixel's front-to-back
// accumulation in emission order (opacities(), kbuffer.h). Same float operations per segment as Shading::segment,
// so the image is the per-fragment one bit for bit.
class SegmentBatch {
 public:
  static constexpr int kSize = 1024;
  SegmentBatch(const Shading& shade, Pair2* px) : tau_(float(shade.tau0)), px_(px) {}
  // n1 -> n2 at pixel p through the boundary logic; returns whether it composites.
  int64_t add(int64_t p, uint64_t n1, float v1, uint64_t n2, float v2) {
    PixelAccum& acc = px_[p].acc;
    acc.inside ^= bool(n1 & 1);
    if (!acc.inside) return 0;
    pixel_[n_] = int32_t(p);
    s_[n_] = Shading::mean(v1, v2);
    dd_[n_] = d_of(n2) - d_of(n1);
    if (++n_ == kSize) drain();
    return 1;
  }
  void drain() {
    float alpha[kSize];
    if (avx2_)
      opacities_avx2(tau_, s_, dd_, alpha, n_);
    else
      opacities(tau_, s_, dd_, alpha, n_);
    for (int i = 0; i < n_; ++i) Shading::accumulate(px_[pixel_[i]].acc, s_[i], alpha[i]);
    n_ = 0;
  }

 private:
  float tau_;
  bool avx2_ = cpu_has_avx2();
  Pair2* px_;
  int n_ = 0;
  int32_t pixel_[kSize];
  float s_[kSize], dd_[kSize];
};

RenderStats render_band2(const FaceData& fd, const SampleFrame& frame, const FaceBins& b, int q,
                         const Shading& shade, Image& image) {
  const int row0 = q * b.rows_per_band, row1 = std::min(frame.rows(), row0 + b.rows_per_band);
  const int64_t np = int64_t(row1 - row0) * frame.cols();
  if (b.start[q] == b.start[q + 1]) {  // no face reaches the band (a third on the helix)
    std::fill_n(image.rgb.begin() + 3 * int64_t(row0) * frame.cols(), 3 * np, 0.f);
    return {};
  }
  // Per-thread buffer kept from band to band and frame to frame (fresh ones cost page
  // faults every frame).
  thread_local std::vector<Pair2> buffer;
  buffer.resize(np);
  Pair2* px = buffer.data();
  for (int64_t p = 0; p < np; ++p) px[p].acc = PixelAccum{}, px[p].count = 0;
  int64_t frags = 0, segs = 0;
  SegmentBatch batch(shade, px);
  scan_band(fd, frame, b, q, [&](int64_t p, const KEntry& e) __attribute__((always_inline)) {
    ++frags;
    Pair2& s = px[p];
    const uint64_t kf = key_of(e);
    if (s.count < 2) {
      if (s.count++ == 0) {
        s.k0 = kf, s.v0 = e.v;
      } else if (kf < s.k0) {
        s.k1 = s.k0, s.v1 = s.v0, s.k0 = kf, s.v0 = e.v;
      } else {
        s.k1 = kf, s.v1 = e.v;
      }
      return;
    }
    // n1 = min(e0, f), m = max(e0, f); n2 = min(m, e1) stays as e0, max(m, e1) as e1.
    const bool f_first = kf < s.k0;
    const uint64_t n1 = f_first ? kf : s.k0, m = f_first ? s.k0 : kf;
    const float v1 = f_first ? e.v : s.v0, vm = f_first ? s.v0 : e.v;
    const bool m_second = m < s.k1;
    const uint64_t n2 = m_second ? m : s.k1, far = m_second ? s.k1 : m;
    const float v2 = m_second ? vm : s.v1, vfar = m_second ? s.v1 : vm;
    s.k0 = n2, s.v0 = v2, s.k1 = far, s.v1 = vfar;
    segs += batch.add(p, n1, v1, n2, v2);
  });
  for (int64_t p = 0; p < np; ++p)
    if (px[p].count == 2) segs += batch.add(p, px[p].k0, px[p].v0, px[p].k1, px[p].v1);
  batch.drain();
  for (int64_t p = 0; p < np; ++p) store_pixel(image, int64_t(row0) * frame.cols() + p, px[p].acc);
  return {frags, segs};
}

// Any k: separate arrays and kbuffer_insert (the analysis' own k-buffer).
RenderStats render_band_any(const FaceData& fd, const SampleFrame& frame, const FaceBins& b, int q, int k,
                            const Shading& shade, Image& image) {
  const int row0 = q * b.rows_per_band, row1 = std::min(frame.rows(), row0 + b.rows_per_band);
  const int64_t np = int64_t(row1 - row0) * frame.cols();
  int64_t segs = 0, frags = 0;
  thread_local std::vector<KEntry> entries;
  thread_local std::vector<uint8_t> count;
  thread_local std::vector<PixelAccum> acc;
  entries.resize(np * k);
  count.assign(np, 0);
  acc.assign(np, PixelAccum{});
  scan_band(fd, frame, b, q, [&](int64_t p, const KEntry& e) {
    ++frags;
    kbuffer_insert(&entries[p * k], count[p], k, e, [&](const KEntry& n1, const KEntry& n2) {
      segs += shade.segment(acc[p], n1, n2);
    });
  });
  for (int64_t p = 0; p < np; ++p) {
    kbuffer_flush(&entries[p * k], count[p], [&](const KEntry& n1, const KEntry& n2) {
      segs += shade.segment(acc[p], n1, n2);
    });
    store_pixel(image, int64_t(row0) * frame.cols() + p, acc[p]);
  }
  return {frags, segs};
}

}  // namespace

RenderStats render_kbuffer(const FaceData& fd, const Camera& view,
                           const std::vector<int32_t>& face_order, int k, Image& image,
                           FaceBins* scratch, RasterRule rule) {
  check_k(k);
  const SampleFrame frame(view, 1, rule);
  FaceBins local;
  FaceBins& b = scratch ? *scratch : local;
  bin_faces(fd, frame, face_order, b, k == 2 ? kBandRowsK2 : kBandRows);
  image.width = frame.cols();
  image.height = frame.rows();
  image.rgb.resize(size_t(3) * frame.num_samples());  // every pixel is stored below
  const Shading shade{fd.tau0};
  // Per band, written once per band (a counter per fragment here would share lines).
  std::vector<RenderStats> per_band(b.bands);
  // Bands from a shared queue, the most items first (largest first: with a third of the
  // bands empty and the largest ~9% of the work on the helix, a split of the band range left
  // one thread idle at the end); bands are independent, so the result does not depend on it.
  std::vector<int> queue(b.bands);
  std::iota(queue.begin(), queue.end(), 0);
  std::stable_sort(queue.begin(), queue.end(), [&](int x, int y) {
    return b.start[x + 1] - b.start[x] > b.start[y + 1] - b.start[y];
  });
  std::atomic<int> next{0};
  const int workers = static_cast<int>(std::min(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
      static_cast<size_t>(tbb::this_task_arena::max_concurrency())));
  tbb::parallel_for(0, std::max(1, workers), [&](int) {
    for (int i; (i = next.fetch_add(1, std::memory_order_relaxed)) < b.bands;) {
      const int q = queue[i];
      per_band[q] = k == 2 ? render_band2(fd, frame, b, q, shade, image)
                           : render_band_any(fd, frame, b, q, k, shade, image);
    }
  }, tbb::simple_partitioner());
  RenderStats total;
  for (const RenderStats& s : per_band) {
    total.fragments += s.fragments;
    total.segments += s.segments;
  }
  return total;
}

int64_t Analysis::pixels_k_above(int kk) const {
  int64_t n = 0;
  for (size_t i = kk + 1; i < k_histogram.size(); ++i) n += k_histogram[i];
  return n;
}

Analysis analyze(const FaceData& fd, const Camera& view, const std::vector<int32_t>& face_order,
                 int k, const AnalysisOptions& opt) {
  check_k(k);
  const SampleFrame frame(view, 1);
  FaceBins b;
  bin_faces(fd, frame, face_order, b);
  const int cols = frame.cols();
  Analysis a;
  a.k = k;
  a.k_needed.assign(frame.num_samples(), 0);
  a.violating.assign(frame.num_samples(), 0);
  for (Image* img : {&a.kbuffer_image, &a.exact_image}) {
    img->width = cols;
    img->height = frame.rows();
    img->rgb.assign(size_t(3) * frame.num_samples(), 0.f);
  }
  const Shading shade{fd.tau0}, reference{fd.tau0, true};  // k-buffer as rendered; exact in double
  struct BandOut {
    int64_t fragments = 0, covered = 0, violating = 0, bad_segments = 0;
    int max_list = 0;
    std::vector<int64_t> hist;
    std::vector<int32_t> seg_count;  // per pixel of the band
    std::vector<Segment> segs;
  };
  std::vector<BandOut> outs(b.bands);
  tbb::parallel_for(0, b.bands, [&](int q) {
    BandOut& o = outs[q];
    const int row0 = q * b.rows_per_band, row1 = std::min(frame.rows(), row0 + b.rows_per_band);
    const int64_t np = int64_t(row1 - row0) * cols;
    // The band's fragment stream, then grouped per pixel in arrival order (stable).
    std::vector<std::pair<int32_t, KEntry>> stream;
    scan_band(fd, frame, b, q,
              [&](int64_t p, const KEntry& e) { stream.emplace_back(int32_t(p), e); });
    std::vector<int64_t> off(np + 1, 0);
    for (const auto& s : stream) ++off[s.first + 1];
    std::partial_sum(off.begin(), off.end(), off.begin());
    std::vector<KEntry> frag(stream.size());
    {
      std::vector<int64_t> fill(off.begin(), off.end() - 1);
      for (const auto& s : stream) frag[fill[s.first]++] = s.second;
    }
    o.fragments = static_cast<int64_t>(stream.size());
    stream = {};
    if (opt.record_segments) o.seg_count.assign(np, 0);
    KCounter kc;
    std::vector<KEntry> sorted;
    std::vector<double> neg_rank;
    std::vector<std::pair<int32_t, int32_t>> exact_pairs;
    KEntry buf[kMaxK];
    for (int64_t p = 0; p < np; ++p) {
      const int n = static_cast<int>(off[p + 1] - off[p]);
      if (n == 0) continue;
      const KEntry* in = frag.data() + off[p];
      ++o.covered;
      o.max_list = std::max(o.max_list, n);
      // A-buffer: the exact front-to-back order, and each fragment's rank in it.
      sorted.assign(in, in + n);
      std::sort(sorted.begin(), sorted.end(), nearer);
      neg_rank.resize(n);
      for (int i = 0; i < n; ++i) {
        const int r = static_cast<int>(
            std::lower_bound(sorted.begin(), sorted.end(), in[i], nearer) - sorted.begin());
        neg_rank[i] = -r;  // earlier fragment e farther than f <=> -rank(e) < -rank(f)
      }
      const int need = 1 + kc.max_k(neg_rank.data(), neg_rank.data(), n);
      a.k_needed[int64_t(row0) * cols + p] = static_cast<uint8_t>(std::min(need, 255));
      if (o.hist.size() <= size_t(need)) o.hist.resize(need + 1, 0);
      ++o.hist[need];
      // Exact compositing: consecutive pairs of the sorted list.
      PixelAccum exact;
      exact_pairs.clear();
      for (int i = 0; i + 1 < n; ++i) {
        reference.segment(exact, sorted[i], sorted[i + 1]);
        exact_pairs.emplace_back(sorted[i].tag, sorted[i + 1].tag);
      }
      store_pixel(a.exact_image, int64_t(row0) * cols + p, exact);
      // The k-buffer on the same stream, pair by pair against the exact sequence.
      PixelAccum acc;
      uint8_t count = 0;
      size_t pos = 0;
      int64_t bad = 0;
      const auto seg = [&](const KEntry& n1, const KEntry& n2) {
        if (pos >= exact_pairs.size() || exact_pairs[pos] != std::make_pair(n1.tag, n2.tag)) ++bad;
        ++pos;
        if (shade.segment(acc, n1, n2) && opt.record_segments) {
          o.segs.push_back({n1.d, n2.d, n1.face(), n2.face()});
          ++o.seg_count[p];
        }
      };
      for (int i = 0; i < n; ++i) kbuffer_insert(buf, count, k, in[i], seg);
      kbuffer_flush(buf, count, seg);
      store_pixel(a.kbuffer_image, int64_t(row0) * cols + p, acc);
      o.bad_segments += bad;
      o.violating += bad > 0;
      a.violating[int64_t(row0) * cols + p] = bad > 0;
    }
  });
  for (BandOut& o : outs) {
    a.fragments += o.fragments;
    a.covered_pixels += o.covered;
    a.violating_pixels += o.violating;
    a.violating_segments += o.bad_segments;
    a.max_list = std::max(a.max_list, o.max_list);
    if (a.k_histogram.size() < o.hist.size()) a.k_histogram.resize(o.hist.size(), 0);
    for (size_t i = 0; i < o.hist.size(); ++i) a.k_histogram[i] += o.hist[i];
  }
  a.max_k_needed = a.k_histogram.empty() ? 0 : static_cast<int>(a.k_histogram.size()) - 1;
  if (opt.record_segments) {
    a.seg_offsets.assign(1, 0);
    for (BandOut& o : outs) {
      for (int32_t c : o.seg_count) a.seg_offsets.push_back(a.seg_offsets.back() + c);
      a.segments.insert(a.segments.end(), o.segs.begin(), o.segs.end());
    }
  }
  a.image_error = image_error(a.kbuffer_image, a.exact_image);
  return a;
}

Image k_needed_image(const Analysis& a, int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgb.assign(size_t(3) * width * height, 0.f);
  for (size_t p = 0; p < a.k_needed.size() && p < size_t(width) * height; ++p) {
    const int k = a.k_needed[p];
    if (k == 0) continue;
    const float r = k > 2 ? 1.f : 0.1f, g = k > 6 ? 0.1f : 0.8f;
    img.rgb[3 * p] = r;
    img.rgb[3 * p + 1] = g;
    img.rgb[3 * p + 2] = 0.1f;
  }
  return img;
}

}  // namespace vob::havs
