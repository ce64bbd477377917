#include "harness/oracle/oracle.h"

#include <algorithm>
#include <limits>
#include <span>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "harness/oracle/k_metric.h"
#include "harness/raster/fragments.h"
#include "harness/scene/input_error.h"

namespace vob {

int64_t OracleResult::samples_with_k_above(int k) const {
  int64_t n = 0;
  for (size_t i = std::max(0, k + 1); i < k_histogram.size(); ++i) n += k_histogram[i];
  return n;
}

nlohmann::json OracleResult::to_json() const {
  nlohmann::json j{{"supersample", supersample},
          {"samples", samples},
          {"fragments", fragments},
          {"covered_pixels", covered_pixels},
          {"violating_pixels", violating_pixels},
          {"violating_fragments", violating_fragments},
          {"violating_pairs", pairs_counted ? nlohmann::json(violating_pairs) : nlohmann::json(nullptr)},
          {"max_k", max_k},
          {"max_list", max_list},
          {"k_histogram", k_histogram},
          {"examples", examples},
          {"overlapping_pairs", overlapping_pairs},
          {"overlap_examples", overlap_examples}};
  if (rule_cycles) j["rule_cycles"] = rule_cycles->to_json();
  return j;
}

namespace {

struct Example {
  int sx, sy;
  Fragment late, blocker;
};

struct OverlapExample {
  int sx, sy;
  Fragment a, b;  // a has the smaller cell id
};

struct BandStats {
  int64_t fragments = 0, covered = 0, violating_samples = 0, violating_fragments = 0;
  int max_list = 0;
  std::vector<int64_t> khist{0};
  std::vector<uint64_t> pairs;  // (late << 32) | blocker
  std::vector<Example> examples;
  std::vector<uint64_t> overlaps;  // (smaller cell << 32) | larger cell
  std::vector<OverlapExample> overlap_examples;
};

// Neighbouring samples repeat the same pairs; a small direct-mapped table of recent pairs
// drops most repeats before the exact sort-and-unique of each band.
class PairFilter {
 public:
  bool fresh(uint64_t pair) {
    uint64_t& slot = table_[(pair * 0x9E3779B97F4A7C15ull) >> (64 - kBits)];
    if (slot == pair + 1) return false;
    slot = pair + 1;  // 0 marks an empty slot
    return true;
  }
  void clear() { std::fill(std::begin(table_), std::end(table_), 0); }

 private:
  static constexpr int kBits = 12;
  uint64_t table_[1 << kBits] = {};
};

struct Scratch {
  FragmentLists lists;
  KCounter counter;
  PairFilter pairs, overlap_pairs;
  std::vector<double> in, query;
  std::vector<int> by_t_in, active;
  std::vector<int64_t> per_prim;  // OracleOptions::per_primitive, this thread's counts
};

size_t primitive_id_count(const Scene& scene) {
  switch (scene.kind()) {
    case SceneKind::Cells: return scene.mesh().num_cells();
    case SceneKind::Triangles: return scene.soup().num_triangles();
    case SceneKind::Voxels: return scene.grid().num_voxels();
  }
  return 0;
}

// Cells: every pair of segments at one sample overlapping by more than `tol`. A sweep in
// t_in order keeps the segments still open; in a valid mesh that list holds at most one
// segment reaching past the next t_in (by less than tol), so the sweep is linear. A correct
// back-to-front order already lists t_in decreasing, which skips the sort.
template <class Report>
void find_overlaps(std::span<const Fragment> frags, double tol, Scratch& s, Report&& report) {
  const int n = int(frags.size());
  auto& idx = s.by_t_in;
  idx.resize(n);
  bool descending = true;
  for (int j = 1; j < n && descending; ++j) descending = frags[j].t_in <= frags[j - 1].t_in;
  for (int j = 0; j < n; ++j) idx[j] = descending ? n - 1 - j : j;
  if (!descending)
    std::sort(idx.begin(), idx.end(), [&](int a, int b) { return frags[a].t_in < frags[b].t_in; });
  auto& active = s.active;
  active.clear();
  for (const int i : idx) {
    const Fragment& f = frags[i];
    size_t keep = 0;
    for (const int j : active) {
      const Fragment& g = frags[j];
      if (!(g.t_out - f.t_in > tol)) continue;  // closed before f opens (t_in only grows)
      active[keep++] = j;
      if (std::min(f.t_out, g.t_out) - f.t_in > tol) report(f, g);
    }
    active.resize(keep);
    active.push_back(i);
  }
}

nlohmann::json depth_json(const Fragment& f, bool cells) {
  if (cells) return nlohmann::json::array({f.t_in, f.t_out});
  return f.t_in;
}

}  // namespace

OracleResult check_ordering(const Scene& scene, const Camera& view,
                            const std::vector<int32_t>& order, const OracleOptions& opt) {
  if (opt.max_examples < 0) throw InputError("oracle", "max_examples", "must be >= 0");
  CollectOptions co;
  co.supersample = opt.supersample;
  co.splat_radius_px = opt.splat_radius_px;
  co.raster = opt.raster;
  const FragmentCollector collector(scene, view, order, co);
  const SampleFrame& frame = collector.frame();
  const bool cells = scene.kind() == SceneKind::Cells;
  const bool depth24 = opt.raster == RasterRule::gl && !cells;
  const double tie = kDepthTieRelative *
                     (scene.bounds().radius() + length(view.eye - scene.bounds().center()));
  const size_t max_examples = static_cast<size_t>(opt.max_examples);
  const double overlap_tol = 0.5 * collector.min_segment();  // oracle.h: half the shortest segment

  // Per sample (bands write disjoint rows), folded to pixels at the end.
  std::vector<uint8_t> sample_mask(opt.violation_mask ? frame.num_samples() : 0, 0);
  const int nb = collector.num_bands();
  std::vector<BandStats> bands(nb);
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(0, nb, [&](int b) {
    Scratch& s = scratch.local();
    if (opt.per_primitive && s.per_prim.empty()) s.per_prim.assign(primitive_id_count(scene), 0);
    BandStats& st = bands[b];
    collector.collect_band(b, s.lists);
    s.pairs.clear();
    s.overlap_pairs.clear();
    const FragmentLists& fl = s.lists;
    st.fragments = int64_t(fl.fragments.size());
    for (int64_t i = 0; i < fl.num_samples(); ++i) {
      const auto frags = fl.local(i);
      const int n = int(frags.size());
      if (n == 0) {
        ++st.khist[0];
        continue;
      }
      ++st.covered;
      st.max_list = std::max(st.max_list, n);
      if (cells && n > 1)
        find_overlaps(frags, overlap_tol, s, [&](const Fragment& f, const Fragment& g) {
          const Fragment& a = f.prim < g.prim ? f : g;
          const Fragment& b = f.prim < g.prim ? g : f;
          const uint64_t pair = uint64_t(uint32_t(a.prim)) << 32 | uint32_t(b.prim);
          if (s.overlap_pairs.fresh(pair)) st.overlaps.push_back(pair);
          if (st.overlap_examples.size() < max_examples) {
            const int sy = fl.row0 + int(i / fl.cols), sx = int(i % fl.cols);
            st.overlap_examples.push_back({sx, sy, a, b});
          }
        });
      s.in.resize(n);
      s.query.resize(n);
      if (depth24) {  // the 24-bit value llvmpipe's depth test compares (fragments.h); equal values tie
        for (int j = 0; j < n; ++j) s.in[j] = s.query[j] = frags[j].t_out;
      } else {
        for (int j = 0; j < n; ++j) {
          s.in[j] = frags[j].t_in;
          s.query[j] = cells ? frags[j].mid() : frags[j].t_in - tie;
        }
      }
      // z-buffer pass: nearest key drawn so far and who holds it.
      double nearest = std::numeric_limits<double>::infinity();
      int holder = -1;
      bool violated = false;
      for (int j = 0; j < n; ++j) {
        if (s.query[j] > nearest) {
          violated = true;
          ++st.violating_fragments;
          if (opt.per_primitive) ++s.per_prim[frags[j].prim];
          const uint64_t pair = uint64_t(uint32_t(frags[j].prim)) << 32 | uint32_t(frags[holder].prim);
          if (s.pairs.fresh(pair)) st.pairs.push_back(pair);
          if (st.examples.size() < max_examples) {
            const int sy = fl.row0 + int(i / fl.cols), sx = int(i % fl.cols);
            st.examples.push_back({sx, sy, frags[j], frags[holder]});
          }
        }
        if (s.in[j] < nearest) nearest = s.in[j], holder = j;
      }
      int k = 0;
      if (violated) {
        ++st.violating_samples;
        if (opt.violation_mask) sample_mask[int64_t(fl.row0) * fl.cols + i] = 1;
        k = s.counter.max_k(s.in.data(), s.query.data(), n);
      }
      if (k >= int(st.khist.size())) st.khist.resize(k + 1, 0);
      ++st.khist[k];
    }
    for (auto* v : {&st.pairs, &st.overlaps}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
      v->shrink_to_fit();
    }
  });

  OracleResult r;
  r.supersample = frame.supersample();
  r.samples = frame.num_samples();
  std::vector<uint64_t> pairs, overlaps;
  size_t npairs = 0;
  for (const BandStats& st : bands) npairs += st.pairs.size();
  pairs.reserve(npairs);
  for (BandStats& st : bands) {
    r.fragments += st.fragments;
    r.covered_pixels += st.covered;
    r.violating_pixels += st.violating_samples;
    r.violating_fragments += st.violating_fragments;
    r.max_list = std::max(r.max_list, st.max_list);
    if (st.khist.size() > r.k_histogram.size()) r.k_histogram.resize(st.khist.size(), 0);
    for (size_t k = 0; k < st.khist.size(); ++k) r.k_histogram[k] += st.khist[k];
    pairs.insert(pairs.end(), st.pairs.begin(), st.pairs.end());
    std::vector<uint64_t>().swap(st.pairs);
    const int S = frame.supersample();
    for (const Example& e : st.examples) {
      if (r.examples.size() >= max_examples) break;
      nlohmann::json j{{"pixel", {e.sx / S, e.sy / S}},
                       {"primitive", e.late.prim},
                       {"depth", depth_json(e.late, cells)},
                       {"blocked_by", e.blocker.prim},
                       {"blocker_depth", depth_json(e.blocker, cells)}};
      if (S > 1) j["subsample"] = {e.sx % S, e.sy % S};
      r.examples.push_back(std::move(j));
    }
    overlaps.insert(overlaps.end(), st.overlaps.begin(), st.overlaps.end());
    for (const OverlapExample& e : st.overlap_examples) {
      if (r.overlap_examples.size() >= max_examples) break;
      nlohmann::json j{{"cells", {e.a.prim, e.b.prim}},
                       {"pixel", {e.sx / S, e.sy / S}},
                       {"segments", {depth_json(e.a, true), depth_json(e.b, true)}}};
      if (S > 1) j["subsample"] = {e.sx % S, e.sy % S};
      r.overlap_examples.push_back(std::move(j));
    }
  }
  std::sort(overlaps.begin(), overlaps.end());
  r.overlapping_pairs = int64_t(std::unique(overlaps.begin(), overlaps.end()) - overlaps.begin());
  tbb::parallel_sort(pairs.begin(), pairs.end());
  r.violating_pairs = int64_t(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  r.max_k = int(r.k_histogram.size()) - 1;
  if (opt.raster == RasterRule::gl && r.violating_fragments > 0 && r.overlapping_pairs == 0)
    r.rule_cycles = find_rule_cycles(collector, cells);
  if (opt.per_primitive) {
    r.violating_fragments_per_primitive.assign(primitive_id_count(scene), 0);
    for (const Scratch& s : scratch)
      for (size_t i = 0; i < s.per_prim.size(); ++i) r.violating_fragments_per_primitive[i] += s.per_prim[i];
  }
  if (opt.violation_mask) {
    const int S = frame.supersample();
    r.mask_width = frame.cols() / S;
    r.mask_height = frame.rows() / S;
    if (S == 1) {
      r.violation_mask = std::move(sample_mask);
    } else {
      r.violation_mask.assign(size_t(r.mask_width) * r.mask_height, 0);
      for (int sy = 0; sy < frame.rows(); ++sy)
        for (int sx = 0; sx < frame.cols(); ++sx)
          if (sample_mask[int64_t(sy) * frame.cols() + sx])
            r.violation_mask[size_t(sy / S) * r.mask_width + sx / S] = 1;
    }
  }
  return r;
}

}  // namespace vob
