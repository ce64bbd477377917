#include "algorithms/stencil/layer_extraction.h"

#include <algorithm>

namespace vob::stencil {

void add_layer_counters(const LayerResult& r, Ordering& out) {
  auto& k = out.counters;
  k["layers"] = r.layers;
  k["candidate_passes"] = double(r.candidate_passes);
  k["complexity_passes"] = double(r.complexity_passes);
  k["passes"] = double(r.candidate_passes + r.complexity_passes);
  k["reads"] = double(r.reads);
  k["pixels_read"] = double(r.pixels_read);
  k["blocks_read"] = double(r.blocks_read);
  k["covered_pixels"] = double(r.covered_pixels);
  k["fragments"] = double(r.fragments);
  k["average_depth_complexity"] = r.average_depth_complexity();
  k["max_stencil"] = r.max_stencil;
  k["removals"] = double(r.removals);
  k["uncovered_removals"] = double(r.uncovered_removals);
  k["tie_pixels"] = double(r.tie_pixels);
  k["forced"] = double(r.forced.size());
}

nlohmann::json extract_parameters(const std::string& backend, const ExtractOptions& opt) {
  nlohmann::json j{{"backend", backend}, {"variant", opt.blocked ? "blocked" : "naive"}};
  if (opt.blocked) j["block"] = opt.block;
  j["cycles"] = opt.break_cycles ? "break" : "stop";
  return j;
}

PixelRect LayerExtractor::block_rect(int32_t b) const {
  if (whole_) return {0, 0, w_, h_};
  const int bx = b % bw_, by = b / bw_;
  const int x = bx * block_, y = by * block_;
  return {x, y, std::min(block_, w_ - x), std::min(block_, h_ - y)};
}

void LayerExtractor::read_blocks(LayerBackend& backend, const std::vector<int32_t>& blocks,
                                 bool stencil, LayerResult& out) {
  for (int32_t b : blocks) {
    const PixelRect r = block_rect(b);
    backend.read_colour(r, (stencil ? far_ : cand_).data());
    ++out.reads;
    out.pixels_read += int64_t(r.w) * r.h;
    if (stencil) {
      backend.read_stencil(r, stencil_.data());
      ++out.reads;
      out.pixels_read += int64_t(r.w) * r.h;
    }
    if (!whole_) ++out.blocks_read;
  }
}

void LayerExtractor::run(LayerBackend& backend, int32_t n, const Camera& view,
                         const ExtractOptions& opt, PhaseClock& clock, LayerResult& out,
                         const PixelSink* sink) {
  out = LayerResult{};
  w_ = view.width;
  h_ = view.height;
  whole_ = !opt.blocked;
  block_ = opt.blocked ? opt.block : std::max(w_, h_);
  bw_ = (w_ + block_ - 1) / block_;
  bh_ = (h_ + block_ - 1) / block_;
  const size_t pixels = size_t(w_) * h_;
  cand_.assign(pixels, 0);
  far_.assign(pixels, 0);
  stencil_.assign(pixels, 0);
  out.layer.assign(size_t(n), -1);
  out.visible.assign(size_t(n), 0);
  in_f_.assign(size_t(n), 0);
  front_pixels_.assign(size_t(n), 0);
  behind_pixels_.assign(size_t(n), 0);
  blocker_.assign(size_t(n), -1);
  t_.resize(size_t(n));
  for (int32_t i = 0; i < n; ++i) t_[size_t(i)] = i;
  active_.clear();
  for (int32_t b = 0; b < (whole_ ? 1 : bw_ * bh_); ++b) active_.push_back(b);

  bool first_round = true;
  while (!t_.empty()) {
    // Steps 1-2: candidate pass over T.
    {
      auto p = clock.phase("render");
      backend.render_candidates(t_);
      backend.finish();
      ++out.candidate_passes;
    }
    {
      auto p = clock.phase("read");
      read_blocks(backend, active_, false, out);
    }
    // Step 3: F = the primitives in the item buffer; blocks left empty are dropped.
    {
      auto p = clock.phase("scan");
      f_.clear();
      next_.clear();
      for (int32_t b : active_) {
        const PixelRect r = block_rect(b);
        int64_t covered = 0;
        for (int y = r.y; y < r.y + r.h; ++y) {
          const uint32_t* row = &cand_[size_t(y) * w_];
          for (int x = r.x; x < r.x + r.w; ++x) {
            const uint32_t c = row[x];
            if (!c) continue;
            ++covered;
            ++front_pixels_[c - 1];
            if (!in_f_[c - 1]) {
              in_f_[c - 1] = 1;
              f_.push_back(int32_t(c - 1));
            }
          }
        }
        if (covered || whole_) next_.push_back(b);
        if (first_round) out.covered_pixels += covered;
      }
      active_.swap(next_);
      std::sort(f_.begin(), f_.end());
      for (int32_t id : f_) out.visible[size_t(id)] = 1;
    }
    first_round = false;
    if (f_.empty()) break;  // what is left covers no pixel
    f0_ = f_;  // the candidates of this round

    // Step 4: remove candidates covered by something in T until F is a layer.
    f_blocks_ = active_;
    while (true) {
      {
        auto p = clock.phase("render");
        draw_.assign(f_.rbegin(), f_.rend());  // descending: ties keep C's primitive
        backend.render_complexity(draw_);
        backend.finish();
        ++out.complexity_passes;
      }
      {
        auto p = clock.phase("read");
        read_blocks(backend, f_blocks_, true, out);
      }
      int64_t removed = 0;
      bool need_more = false;
      {
        auto p = clock.phase("scan");
        next_.clear();
        for (int32_t b : f_blocks_) {
          const PixelRect r = block_rect(b);
          bool any = false;
          for (int y = r.y; y < r.y + r.h; ++y) {
            const size_t row = size_t(y) * w_;
            for (int x = r.x; x < r.x + r.w; ++x) {
              const int s = stencil_[row + x];
              if (!s) continue;
              any = true;
              out.max_stencil = std::max(out.max_stencil, s);
              const uint32_t g = far_[row + x], c = cand_[row + x];
              if (g == c || g == 0) {  // g == 0 cannot happen: every fragment passes GEQUAL 0
                if (s > 1 && g) ++out.tie_pixels;
                continue;
              }
              ++behind_pixels_[g - 1];
              if (c && blocker_[g - 1] < 0) blocker_[g - 1] = int32_t(c - 1);
              if (in_f_[g - 1] == 1) {
                in_f_[g - 1] = 2;  // removed in this pass
                ++removed;
                if (s == 1) ++out.uncovered_removals;
              }
              if (s >= 3 || (s == 2 && (c == 0 || in_f_[c - 1] == 0))) need_more = true;
            }
          }
          if (any || whole_) next_.push_back(b);
        }
        f_blocks_.swap(next_);
        size_t k = 0;
        for (int32_t id : f_) {
          if (in_f_[size_t(id)] == 2) {
            in_f_[size_t(id)] = 0;  // back in T (T still lists it)
          } else {
            f_[k++] = id;
          }
        }
        f_.resize(k);
        out.removals += removed;
      }
      if (removed == 0 || !need_more || f_.empty()) break;
    }

    // Step 5: no layer this round -> stop (or break the cycle); else T_i = F.
    if (f_.empty() && opt.break_cycles) {
      const int32_t best = forced_candidate();
      f_.assign(1, best);
      out.forced.push_back(best);
    }
    for (int32_t id : f0_) front_pixels_[size_t(id)] = behind_pixels_[size_t(id)] = 0, blocker_[size_t(id)] = -1;
    if (f_.empty()) break;
    const int L = out.layers++;
    {
      auto p = clock.phase("scan");
      for (int32_t id : f_) {
        out.layer[size_t(id)] = L;
        in_f_[size_t(id)] = 0;
      }
      size_t k = 0;
      for (int32_t id : t_)
        if (out.layer[size_t(id)] < 0) t_[k++] = id;
      t_.resize(k);
      int64_t foot = 0;
      for (int32_t b : active_) {
        const PixelRect r = block_rect(b);
        for (int y = r.y; y < r.y + r.h; ++y) {
          const size_t row = size_t(y) * w_;
          for (int x = r.x; x < r.x + r.w; ++x) {
            const uint32_t c = cand_[row + x];
            if (c && out.layer[c - 1] == L) {
              ++foot;
              if (sink) (*sink)(int64_t(row + x), int32_t(c - 1), L);
            }
          }
        }
      }
      out.footprint.push_back(foot);
      out.fragments += foot;
    }
  }
  for (int32_t id : t_) {
    if (out.visible[size_t(id)])
      ++out.unclassified_visible;
    else
      ++out.unclassified_no_pixel;
  }
}

int32_t LayerExtractor::forced_candidate() {
  // Every candidate of a stuck round was found behind another (its blocker), so following
  // blockers from any candidate ends on a cycle. Forcing one of the cycle breaks it at the
  // cost of its own behind pixels; forcing a candidate that is only behind the cycle (not
  // on it) would draw it in front of what covers it, a violation no order needs.
  cycle_.clear();
  int32_t x = f0_.front();
  while (x >= 0 && in_f_[size_t(x)] != 3) in_f_[size_t(x)] = 3, x = blocker_[size_t(x)];
  for (int32_t id : f0_) in_f_[size_t(id)] = 0;  // (all were back in T: f_ is empty)
  if (x >= 0) {
    int32_t y = x;
    do cycle_.push_back(y), y = blocker_[size_t(y)];
    while (y != x);
  }
  const std::vector<int32_t>& among = cycle_.empty() ? f0_ : cycle_;  // (no blocker recorded: all)
  int32_t best = among.front();
  for (int32_t id : among) {
    const int32_t b = behind_pixels_[size_t(id)], bb = behind_pixels_[size_t(best)];
    if (b < bb || (b == bb && (front_pixels_[size_t(id)] > front_pixels_[size_t(best)] ||
                               (front_pixels_[size_t(id)] == front_pixels_[size_t(best)] && id < best))))
      best = id;
  }
  return best;
}

size_t LayerExtractor::bytes() const {
  return cand_.capacity() * 4 + far_.capacity() * 4 + stencil_.capacity() +
         (t_.capacity() + f_.capacity() + draw_.capacity() + active_.capacity() +
          f_blocks_.capacity() + next_.capacity() + f0_.capacity() + front_pixels_.capacity() +
          behind_pixels_.capacity() + blocker_.capacity() + cycle_.capacity()) * 4 +
         in_f_.capacity();
}

size_t Extraction::bytes() const {
  return extractor.bytes() + (backend ? backend->bytes() : 0) + result.layer.capacity() * 4 +
         result.visible.capacity();
}

std::vector<ParamSpec> extraction_params() {
  return {ParamSpec::choice("backend", "gl", {"gl", "software"},
                            "OpenGL through OSMesa, or the same passes on the harness rasterizer"),
          ParamSpec::choice("variant", "blocked", {"naive", "blocked"},
                            "whole-buffer reads and scans, or only blocks that can still be covered"),
          ParamSpec::integer("block", 64, 8, 1024, "block side in pixels (blocked)"),
          ParamSpec::choice("cycles", "break", {"break", "stop"},
                            "a round that layers nothing forces one candidate (break) or ends the "
                            "extraction (stop, the paper)")};
}

ExtractOptions extract_options(const ResolvedParams& p) {
  ExtractOptions opt;
  opt.blocked = p.get_choice("variant") == "blocked";
  opt.block = p.get_int("block");
  opt.break_cycles = p.get_choice("cycles") == "break";
  return opt;
}

}  // namespace vob::stencil
