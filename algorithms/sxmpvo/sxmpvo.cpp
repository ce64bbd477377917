#include "algorithms/sxmpvo/sxmpvo.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
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
    int64_t tiny = 0;
    for (int64_t t : tiny_) tiny += t;
    k["tiny_path_faces"] = static_cast<double>(tiny);
    k["abuffer_entries"] = static_cast<double>(abuf_.entries());
    k["head_insertions"] = static_cast<double>(abuf_.head_insertions());
    k["head_insertion_rate"] =
        abuf_.entries() ? static_cast<double>(abuf_.head_insertions()) / abuf_.entries() : 1.0;
    k["insertion_walk_steps"] = static_cast<double>(abuf_.walk_steps());
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
    return core_.bytes() + abuffer_bytes() + pn_.bytes() + extra_.bytes() + exterior_bytes() +
           scratch_.capacity() * sizeof(PixEntry);
  }

 private:
  using PixEntry = sxmpvo::PixEntry;
  using PairStats = sxmpvo::PairStats;

  size_t abuffer_bytes() const {  // the lists and the scan's batches
    size_t n = abuf_.bytes();
    for (const auto& batch : batches_) n += batch.capacity() * sizeof(sxmpvo::ABuffer::Raw);
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

  void scan_and_pair(const Camera& view, PairStats& stats) {
    const SampleFrame frame(view, 1);
    const int cols = frame.cols();
    abuf_.reset(frame.num_samples());
    // Each boundary point is projected once, not once per face that has it.
    const std::vector<Vec3>& points = ext_->points;
    projected_.resize(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 8192),
                      [&](const tbb::blocked_range<size_t>& r) {
                        frame.project_all(points.data() + r.begin(), r.size(), projected_.data() + r.begin());
                      });
    // Faces are scanned in storage order, where a face's points, corners and sign lie near
    // the previous face's (in sorted order every face is a cache miss); each entry carries
    // its face's rank in the sorted order, which the A-buffer replays as the arrival order.
    // Runs of faces are scanned in parallel, each into its own batch: the ranks make the
    // lists, counts and relations independent of the threads.
    const size_t b = ext_->face.size();
    const size_t runs = std::max<size_t>(1, std::min<size_t>(64, b / 2048));
    batches_.resize(runs);
    tiny_.assign(runs, 0);
    const sxmpvo::TinyEntriesFn tiny_entries = sxmpvo::tiny_entries();
    tbb::parallel_for(size_t(0), runs, [&](size_t r) {
      // The batch is grown (Raw's constructor leaves it unset) and written by index; the
      // tiny path writes whole steps of four past its count, hence the room it asks for.
      std::vector<sxmpvo::ABuffer::Raw>& batch = batches_[r];
      size_t used = 0;
      // Up to the storage at hand first (free: Raw leaves it unset), doubled beyond it: a
      // batch cut to its count last frame grows back without a new allocation (which came
      // every second frame when it doubled its count: phase III of the second frame of the
      // 1M helix 27-28 ms against 13-14).
      const auto room = [&](size_t k) {
        if (batch.size() >= used + k) return;
        batch.resize(batch.capacity() >= used + k ? batch.capacity() : std::max(2 * batch.capacity(), used + k + 4096));
      };
      PolygonRaster raster;
      const ExteriorFaces& ext = *ext_;
      int64_t tiny = 0;
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
        const Vec3* corners = &ext.corners[4 * i];
        if (kind == sxmpvo::BoxKind::Tiny && n == 3) {
          room(sxmpvo::kTinyEntrySlots);
          used += tiny_entries(frame, corners, s, box, item, rank, batch.data() + used);
          ++tiny;
        } else {
          ProjectedVertex proj[4];
          for (int v = 0; v < n; ++v) proj[v] = projected_[ids[v]];
          if (raster.setup(frame, corners, n, proj))
            raster.scan(frame.bounds(), [&](const RowHits& hits, int k) {  // a batch at a time
              room(static_cast<size_t>(k));
              sxmpvo::ABuffer::Raw* out = batch.data() + used;
              for (int j = 0; j < k; ++j)
                out[j] = {hits.t[j], item, static_cast<int32_t>(int64_t(hits.sy[j]) * cols + hits.sx[j]), rank};
              used += static_cast<size_t>(k);
            });
        }
      }
      batch.resize(used);
      tiny_[r] = tiny;
    });
    for (const auto& batch : batches_) abuf_.append(batch);
    abuf_.gather();
    const double tie = kTieRelative * (radius_ + length(view.eye - centre_));
    pn_.reset(core_.num_cells());
    const int64_t pixels = abuf_.pixels();
    // Lists ordered and paired a few rows at a time, while they are in cache.
    for (int64_t p0 = 0, step = 8 * int64_t(cols); p0 < pixels; p0 += step) {
      const int64_t p1 = std::min(pixels, p0 + step);
      abuf_.order(p0, p1);
      // The occluding cell of a pair is a back-facing entry's just behind a front-facing one
      // (far to near; across two lists the guess only costs a prefetch).
      for (const sxmpvo::PixEntry *e = abuf_.begin(p0), *end = abuf_.begin(p1); e + 1 < end; ++e)
        if (e->front() && !e[1].front()) pn_.prefetch(e[1].cell());
      for (int64_t p = p0; p < p1; ++p) {
        if (p + 8 <= p1 && abuf_.begin(p) == abuf_.begin(p + 8)) {  // eight empty lists
          p += 7;
          continue;
        }
        if (abuf_.head(p) >= 0) sxmpvo::pair_pix_list(abuf_, p, tie, scratch_, pn_, stats);
      }
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
  sxmpvo::ABuffer abuf_;
  sxmpvo::PnLists pn_;
  mpvo::ExtraRelations extra_;
  std::vector<PixEntry> scratch_;
  std::vector<int32_t> rank_;                                // per exterior face
  std::vector<std::vector<sxmpvo::ABuffer::Raw>> batches_;  // per run of faces
  std::vector<int64_t> tiny_;                                // per run: faces on the tiny path
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
