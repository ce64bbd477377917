#include "algorithms/sxmpvo/sxmpvo.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/sxmpvo/abuffer.h"
#include "algorithms/sxmpvo/tiny_faces.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"
#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

// Depths closer than this fraction of (scene radius + eye distance) are a tie: far above
// the rounding of t for faces that touch (~1e-15 relative), far below the oracle's shortest
// segment (kMinSegmentRelative = 1e-10 of the radius) scaled up by the eye distance.
constexpr double kTieRelative = 1e-9;

class SxmpvoOrderer final : public Orderer {
 public:
  explicit SxmpvoOrderer(mpvo::RenumberOption renumber) : renumber_(renumber) {}
  Claims claims() const override { return mpvo::core_claims(false, true); }

  void prepare(const Scene& input, PhaseClock& clock) override {
    core_.prepare(input, clock, renumber_);
    const Scene& scene = core_.scene();  // the input's, or its renumbered copy
    { auto p = clock.phase("exterior faces"); ext_ = &scene.exterior_faces(); }
    auto p = clock.phase("exterior centroids");
    const size_t b = ext_->face.size();
    ext_centroid_.resize(b);
    for (size_t i = 0; i < b; ++i) {
      Vec3 c{};
      const int n = ext_->size[i];
      for (int k = 0; k < n; ++k) c += ext_->corners[4 * i + k];
      ext_centroid_[i] = c * (1.0 / n);
    }
    const Aabb box = scene.mesh().bounds();
    centre_ = (box.lo + box.hi) * 0.5;
    radius_ = 0.5 * length(box.hi - box.lo);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
    }
    {
      auto p = clock.phase("II sort exterior faces");
      sort_exterior_faces(view);
    }
    PairStats stats;
    {
      auto p = clock.phase("III scan faces and add dependencies");
      scan_and_pair(view, stats);
    }
    {
      auto p = clock.phase("IV DFS");
      core_.dfs_all(out, &extra_);
    }
    core_.add_counters(out);
    auto& k = out.counters;
    k["exterior_faces"] = static_cast<double>(ext_->face.size());
    k["tiny_path_faces"] = static_cast<double>(tiny_);
    k["abuffer_entries"] = static_cast<double>(entries_);
    k["head_insertions"] = static_cast<double>(head_insertions_);
    k["head_insertion_rate"] = entries_ ? static_cast<double>(head_insertions_) / entries_ : 1.0;
    k["insertion_walk_steps"] = static_cast<double>(walk_steps_);
    k["pix_lists"] = static_cast<double>(stats.lists);
    k["max_pix_list"] = static_cast<double>(stats.max_list);
    k["pn_pairs"] = static_cast<double>(stats.pairs);
    k["pn_relations"] = static_cast<double>(pn_.relations());
    k["pn_found_at_head"] = static_cast<double>(pn_.found_at_head());
    k["pn_moved_to_front"] = static_cast<double>(pn_.moved_to_front());
    k["pn_search_steps"] = static_cast<double>(pn_.search_steps());
    k["tie_reorders"] = static_cast<double>(stats.tie_reorders);
    k["unpaired_entries"] = static_cast<double>(stats.unpaired);
    k["self_pairs"] = static_cast<double>(stats.self_pairs);
    k["bytes_mpvo"] = static_cast<double>(core_.bytes());
    k["bytes_faces"] =
        static_cast<double>(core_.faces().bytes() + core_.scene().face_planes().bytes());
    k["bytes_abuffer"] = static_cast<double>(abuffer_bytes());
    k["bytes_pn"] = static_cast<double>(pn_.bytes() + extra_.bytes());
    k["bytes_exterior"] = static_cast<double>(ext_->bytes() + exterior_bytes());
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + abuffer_bytes() + pn_.bytes() + extra_.bytes() + exterior_bytes();
  }

 private:
  using PixEntry = sxmpvo::PixEntry;
  using PairStats = sxmpvo::PairStats;

  size_t abuffer_bytes() const {  // the bands: their faces, lists, entries and pairs
    size_t n = band_faces_.capacity() * sizeof(BandFace) + band_offset_.capacity() * sizeof(int32_t);
    for (const FaceRun& run : runs_) {
      n += run.faces.capacity() * sizeof(BandFace) + run.in_band.capacity() * sizeof(int32_t);
      for (const auto& entries : run.large) n += entries.bytes();
    }
    for (const BandResult& band : bands_) n += band.pairs.capacity() * sizeof(band.pairs[0]);
    for (const BandScratch& s : band_scratch_)
      n += s.abuf.bytes() + s.raw.bytes() + s.scratch.capacity() * sizeof(PixEntry);
    return n;
  }

  size_t exterior_bytes() const {
    return ext_centroid_.capacity() * sizeof(Vec3) + projected_.capacity() * sizeof(ProjectedVertex) +
           sort_.bytes() + rank_.capacity() * sizeof(int32_t);
  }

  // Exterior faces (indices into the exterior face list), nearest centroid first, and each
  // face's rank in that order.
  void sort_exterior_faces(const Camera& view) {
    const Vec3 eye = view.eye, dir = view.forward();
    const size_t b = ext_centroid_.size();
    sort_.resize(b);
    for (size_t i = 0; i < b; ++i) {
      const Vec3 d = ext_centroid_[i] - eye;
      sort_.keys[i] = static_cast<float>(view.ortho ? dot(d, dir) : length(d));
      sort_.ids[i] = static_cast<int32_t>(i);
    }
    sort_.sort();
    rank_.resize(b);
    for (size_t k = 0; k < b; ++k) rank_[sort_.ids[k]] = static_cast<int32_t>(k);
  }

  // Phase III works a band of kBandRows sample rows at a time: pass 1 finds each exterior
  // face's sample box and the bands a tiny one meets, and rasterizes the larger faces into
  // the bands' entries; pass 2 scans each band's tiny faces into its own A-buffer (with the
  // larger faces' entries), orders its lists and pairs them. Bands run in parallel; the
  // pairs go to the PN lists in band order. One A-buffer for the whole frame did its gather, ordering and
  // pairing on one thread (1M helix, 2 threads: phase III 9.4 ms then, 7.4 in bands; one
  // thread: 0.1-0.3 ms slower in bands there, 0.3 faster on the 20k helix) and held 26 MB
  // where the bands hold 14 (design notes, session 68).
  static constexpr int kBandRows = 32;  // 8 rows: phase III 1.08 times slower (more faces met twice)

  struct BandFace {  // a tiny triangle that a band's rows meet
    int32_t face;    // in the exterior face list
    int32_t item, rank;
    SampleRect box;  // sample_box's box
  };
  struct FaceRun {  // pass 1's output for one run of the exterior face list
    std::vector<BandFace> faces;   // its tiny triangles, in list order
    std::vector<int32_t> in_band;  // per band: how many of them meet it, then where they go
    // per band: the entries of its larger faces (rasterized whole in pass 1, where the
    // rasterizer batches their rows, and sorted into the bands by row)
    std::vector<sxmpvo::ABuffer::RawBatch> large;
    // per band: the face last given a slot in its `large` batch, and that slot
    std::vector<int64_t> slot_face;
    std::vector<int32_t> slot;
    int64_t tiny = 0;
  };
  struct BandResult {  // pass 2's pairs of one band (occluding, occluded), in pixel order
    std::vector<std::pair<int32_t, int32_t>> pairs;
    PairStats stats;
    int64_t entries = 0, head_insertions = 0, walk_steps = 0;
  };
  struct BandScratch {  // per thread
    sxmpvo::ABuffer abuf;
    sxmpvo::ABuffer::RawBatch raw;
    std::vector<PixEntry> scratch;
  };

  // Pass 1: the faces that may cover a sample, each listed in every band its box meets.
  void bin_faces(const SampleFrame& frame) {
    const ExteriorFaces& ext = *ext_;
    const size_t b = ext.face.size();
    const size_t runs = std::max<size_t>(1, std::min<size_t>(64, b / 2048));
    const int bands = (frame.rows() + kBandRows - 1) / kBandRows;
    const int64_t cols = frame.cols();
    runs_.resize(runs);
    tbb::parallel_for(size_t(0), runs, [&](size_t r) {
      FaceRun& run = runs_[r];
      run.faces.clear();
      run.in_band.assign(static_cast<size_t>(bands), 0);
      run.large.resize(static_cast<size_t>(bands));
      for (auto& entries : run.large) entries.clear();
      run.slot_face.assign(static_cast<size_t>(bands), -1);
      run.slot.resize(static_cast<size_t>(bands));
      run.tiny = 0;
      PolygonRaster raster;
      const int8_t* sign = core_.face_signs().data();
      constexpr size_t kAhead = 16;  // the signs are a miss a face (scattered face ids): asked ahead
      for (size_t i = b * r / runs, end = b * (r + 1) / runs; i < end; ++i) {
        if (i + kAhead < end) __builtin_prefetch(sign + ext.face[i + kAhead]);
        const int s = sign[ext.face[i]];
        if (s == 0) continue;  // the eye is in its plane: it covers no sample
        const int n = ext.size[i];
        const int32_t* ids = &ext.vertex[4 * i];
        SampleRect box;
        const sxmpvo::BoxKind kind = sxmpvo::sample_box(frame, projected_.data(), ids, n, box);
        if (kind == sxmpvo::BoxKind::None) continue;
        const int32_t item = ext.cell[i] * 2 + (s > 0 ? 1 : 0), rank = rank_[i];
        if (kind == sxmpvo::BoxKind::Tiny && n == 3) {
          run.faces.push_back({static_cast<int32_t>(i), item, rank, box});
          for (int k = box.y0 / kBandRows, k1 = box.y1 / kBandRows; k <= k1; ++k) ++run.in_band[k];
          ++run.tiny;
          continue;
        }
        ProjectedVertex proj[4];
        for (int v = 0; v < n; ++v) proj[v] = projected_[ids[v]];
        if (!raster.setup(frame, &ext.corners[4 * i], n, proj)) continue;
        raster.scan(frame.bounds(), [&](const RowHits& hits, int m) {  // a batch at a time
          // A triangle's rows come in order: the hits of one band at a time, under one slot.
          for (int h = 0; h < m;) {
            const int band = hits.sy[h] / kBandRows;
            int e = h + 1;
            while (e < m && hits.sy[e] / kBandRows == band) ++e;
            sxmpvo::ABuffer::RawBatch& entries = run.large[band];
            if (run.slot_face[band] != static_cast<int64_t>(i))
              run.slot_face[band] = static_cast<int64_t>(i), run.slot[band] = entries.add_face(item, rank);
            entries.reserve_more(static_cast<size_t>(e - h));
            const sxmpvo::ABuffer::RawBatch::Out out = entries.at(entries.size);
            const int32_t slot = run.slot[band];
            for (int j = h; j < e; ++j) {
              out.t[j - h] = hits.t[j];
              out.key[j - h] =
                  sxmpvo::ABuffer::RawBatch::make_key(static_cast<int32_t>(int64_t(hits.sy[j]) * cols + hits.sx[j]), slot);
            }
            entries.size += static_cast<size_t>(e - h);
            h = e;
          }
        });
      }
    });
    // Counting sort into the bands, run after run within a band: each band lists its faces
    // in list order.
    band_offset_.assign(static_cast<size_t>(bands) + 1, 0);
    int32_t at = 0;
    for (int k = 0; k < bands; ++k) {
      band_offset_[k] = at;
      for (FaceRun& run : runs_) {
        const int32_t n = run.in_band[k];
        run.in_band[k] = at;
        at += n;
      }
    }
    band_offset_[bands] = at;
    band_faces_.resize(static_cast<size_t>(at));
    tbb::parallel_for(size_t(0), runs, [&](size_t r) {
      FaceRun& run = runs_[r];
      for (const BandFace& f : run.faces) {
        for (int k = f.box.y0 / kBandRows, k1 = f.box.y1 / kBandRows; k <= k1; ++k) band_faces_[run.in_band[k]++] = f;
      }
    });
  }

  // Pass 2 for band k: its faces' entries, its lists ordered, their pairs.
  void scan_band(const SampleFrame& frame, int k, double tie, sxmpvo::TinyEntriesFn tiny_entries) {
    BandScratch& s = band_scratch_.local();
    BandResult& out = bands_[k];
    const int cols = frame.cols();
    const int y0 = k * kBandRows, y1 = std::min(frame.rows(), y0 + kBandRows) - 1;
    // The tiny path writes whole steps past its count, hence the room it asks for.
    sxmpvo::ABuffer::RawBatch& raw = s.raw;
    raw.clear();
    const ExteriorFaces& ext = *ext_;
    constexpr int32_t kAhead = 8;  // a band's faces lie apart in the list: their corners asked ahead
    for (int32_t j = band_offset_[k], end = band_offset_[k + 1]; j < end; ++j) {
      if (j + kAhead < end) {
        const char* c = reinterpret_cast<const char*>(&ext.corners[4 * band_faces_[j + kAhead].face]);
        __builtin_prefetch(c);
        __builtin_prefetch(c + 3 * sizeof(Vec3) - 1);
      }
      const BandFace& f = band_faces_[j];
      SampleRect box = f.box;  // its rows in the band
      box.y0 = std::max(box.y0, y0);
      box.y1 = std::min(box.y1, y1);
      raw.reserve_more(sxmpvo::kTinyEntrySlots);
      raw.size += static_cast<size_t>(tiny_entries(frame, &ext.corners[4 * f.face], (f.item & 1) ? 1 : -1, box,
                                                   raw.add_face(f.item, f.rank), raw.at(raw.size)));
    }
    const int64_t pixels = int64_t(y1 - y0 + 1) * cols;
    sxmpvo::ABuffer& abuf = s.abuf;
    abuf.reset(pixels, int64_t(y0) * cols);
    abuf.append(raw);
    for (const FaceRun& run : runs_)
      if (run.large[k].size > 0) abuf.append(run.large[k]);
    abuf.gather();
    abuf.order(0, pixels);
    out.pairs.clear();
    out.stats = PairStats{};
    for (int64_t p = 0; p < pixels; ++p) {
      if (p + 8 <= pixels && abuf.begin(p) == abuf.begin(p + 8)) {  // eight empty lists
        p += 7;
        continue;
      }
      if (abuf.head(p) >= 0)
        sxmpvo::for_each_pix_pair(abuf, p, tie, s.scratch, out.stats,
                                  [&](int32_t occluding, int32_t occluded) { out.pairs.emplace_back(occluding, occluded); });
    }
    out.entries = abuf.entries();
    out.head_insertions = abuf.head_insertions();
    out.walk_steps = abuf.walk_steps();
  }

  void scan_and_pair(const Camera& view, PairStats& stats) {
    const SampleFrame frame(view, 1);
    // Each boundary point is projected once, not once per face that has it.
    const std::vector<Vec3>& points = ext_->points;
    projected_.resize(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 8192),
                      [&](const tbb::blocked_range<size_t>& r) {
                        frame.project_all(points.data() + r.begin(), r.size(), projected_.data() + r.begin());
                      });
    // Faces are visited in storage order, where a face's points, corners and sign lie near
    // the previous face's (in sorted order every face is a cache miss); each entry carries
    // its face's rank in the sorted order, which the A-buffer replays as the arrival order.
    // Bands are scanned in parallel; their pairs are recorded in band order, so the lists,
    // counts and relations do not depend on the threads.
    bin_faces(frame);
    const int bands = static_cast<int>(band_offset_.size()) - 1;
    bands_.resize(static_cast<size_t>(bands));
    const double tie = kTieRelative * (radius_ + length(view.eye - centre_));
    const sxmpvo::TinyEntriesFn tiny_entries = sxmpvo::tiny_entries();
    tbb::parallel_for(0, bands, [&](int k) { scan_band(frame, k, tie, tiny_entries); });
    pn_.reset(core_.num_cells());
    entries_ = head_insertions_ = walk_steps_ = tiny_ = 0;
    for (const FaceRun& run : runs_) tiny_ += run.tiny;
    for (const BandResult& band : bands_) {
      const auto& pairs = band.pairs;
      constexpr size_t kAhead = 8;  // a pair's occluding cell is a miss: asked ahead
      for (size_t j = 0, n = pairs.size(); j < n; ++j) {
        if (j + kAhead < n) pn_.prefetch(pairs[j + kAhead].first);
        pn_.add(pairs[j].first, pairs[j].second);
      }
      stats.lists += band.stats.lists;
      stats.pairs += band.stats.pairs;
      stats.tie_reorders += band.stats.tie_reorders;
      stats.unpaired += band.stats.unpaired;
      stats.self_pairs += band.stats.self_pairs;
      stats.max_list = std::max(stats.max_list, band.stats.max_list);
      entries_ += band.entries;
      head_insertions_ += band.head_insertions;
      walk_steps_ += band.walk_steps;
    }
    pn_.to_relations(extra_);
  }

  mpvo::RenumberOption renumber_;
  mpvo::MpvoCore core_;
  const ExteriorFaces* ext_ = nullptr;     // the scene's exterior faces
  std::vector<Vec3> ext_centroid_;          // and their centroids
  std::vector<ProjectedVertex> projected_;  // per view: window positions of their points
  Vec3 centre_{};
  double radius_ = 0;
  KeySort sort_;
  sxmpvo::PnLists pn_;
  mpvo::ExtraRelations extra_;
  std::vector<int32_t> rank_;  // per exterior face
  // Phase III's bands (per view): pass 1's runs, each band's faces (band k's from
  // band_offset_[k]) and each band's pairs.
  std::vector<FaceRun> runs_;
  std::vector<int32_t> band_offset_;
  std::vector<BandFace> band_faces_;
  std::vector<BandResult> bands_;
  tbb::enumerable_thread_specific<BandScratch> band_scratch_;
  int64_t entries_ = 0, head_insertions_ = 0, walk_steps_ = 0, tiny_ = 0;  // the frame's, over its bands
};

}  // namespace

OrdererInfo sxmpvo_orderer_info() {
  return {"sxmpvo", SceneKind::Cells,
          "Cook et al.'s SXMPVO: MPVO arrows plus pseudo-neighbour relations from an A-buffer "
          "of exterior faces at pixel centres (exact at the image resolution)",
          mpvo::renumber_params(), [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<SxmpvoOrderer>(mpvo::renumber_option(p));
          }};
}

}  // namespace vob
