#include "algorithms/sxmpvo/abuffer.h"

#include <algorithm>

namespace vob::sxmpvo {

void ABuffer::reset(int64_t pixels) {
  pixels_ = pixels;
  raw_.clear();
  batches_.clear();
  entries_ = 0;
  list_.clear();
  offsets_.assign(static_cast<size_t>(pixels) + 1, 0);
  head_insertions_ = walk_steps_ = 0;
}

void ABuffer::gather() {
  // Counting sort by pixel straight into the lists (each entry's rank parked in its `next`
  // until the links are made: one scatter of 16-byte entries, no scratch copy). Each
  // pixel's count becomes its list's end, and the scatter counts it down to the list's
  // start: no cursor array to copy. A list comes out in reverse recording order, which
  // order() does not see (it replays the arrivals by rank).
  int32_t* end = offsets_.data();  // zero since reset(): gather() runs once a frame
  each_raw([&](const Raw& r) { ++end[r.pixel]; });
  for (int64_t p = 1; p < pixels_; ++p) end[p] += end[p - 1];
  offsets_[pixels_] = static_cast<int32_t>(entries_);
  list_.resize(static_cast<size_t>(entries_));
  PixEntry* list = list_.data();
  // Pixels come at random: the place of the entry kDist ahead is asked for before its
  // write (its list end may still move before then; a stale guess only costs a prefetch).
  constexpr size_t kDist = 32;
  const auto scatter = [&](const std::vector<Raw>& raw) {
    const size_t n = raw.size();
    for (size_t i = 0; i < n; ++i) {
      if (i + kDist < n) __builtin_prefetch(&list[end[raw[i + kDist].pixel] - 1], 1);
      const Raw& r = raw[i];
      list[--end[r.pixel]] = {r.t, r.item, r.rank};
    }
  };
  scatter(raw_);
  for (const std::vector<Raw>* b : batches_) scatter(*b);
}

void ABuffer::order(int64_t p0, int64_t p1) {
  PixEntry* list = list_.data();
  // Per pixel, by rank (short lists); then, in rank order, insertion one entry at a time
  // into increasing t, behind every entry not farther than itself (the mirror of "in front
  // of every entry farther than itself" in a decreasing list); then reversed. A new entry
  // passes the entries farther than it.
  for (int64_t p = p0; p < p1; ++p) {
    const int32_t b = offsets_[p], e = offsets_[p + 1];
    if (b == e) continue;
    PixEntry* in = list + b;
    const int32_t k = e - b;
    for (int32_t i = 1; i < k; ++i) {  // by rank (in `next`)
      const PixEntry x = in[i];
      int32_t j = i;
      for (; j > 0 && in[j - 1].next > x.next; --j) in[j] = in[j - 1];
      in[j] = x;
    }
    ++head_insertions_;  // the first entry of a list
    for (int32_t i = 1; i < k; ++i) {  // in place: in[0, i) is the list so far
      const PixEntry x = in[i];
      int32_t j = i;
      while (j > 0 && in[j - 1].t > x.t) {
        in[j] = in[j - 1];
        --j;
      }
      if (j == i) ++head_insertions_;
      walk_steps_ += i - j;
      in[j] = x;
    }
    std::reverse(in, in + k);
    for (int32_t q = b; q < e; ++q) list[q].next = q + 1 < e ? q + 1 : -1;
  }
}

void PnLists::reset(size_t cells) {
  if (head_.size() != cells) {
    head_.assign(cells, -1);
  } else {
    for (int32_t c : touched_) head_[c] = -1;
  }
  touched_.clear();
  pool_.clear();
  queries_ = found_at_head_ = moved_ = steps_ = 0;
}

void PnLists::add(int32_t occluding, int32_t occluded) {
  ++queries_;
  int32_t* link = &head_[occluding];
  if (*link < 0) touched_.push_back(occluding);
  for (int32_t prev = -1, i = *link; i >= 0; prev = i, i = pool_[i].next) {
    ++steps_;
    if (pool_[i].cell != occluded) continue;
    if (prev < 0) {
      ++found_at_head_;
    } else {  // move to front
      pool_[prev].next = pool_[i].next;
      pool_[i].next = *link;
      *link = i;
      ++moved_;
    }
    return;
  }
  pool_.push_back({occluded, *link});
  *link = static_cast<int32_t>(pool_.size() - 1);
}

void PnLists::to_relations(mpvo::ExtraRelations& out) const {
  // The sparse form: only the cells with a list are touched, not every cell of the mesh.
  out.offsets.clear();
  out.not_sink.clear();
  if (out.span.size() != head_.size()) out.span.assign(head_.size(), {0, 0});
  out.cells = touched_;
  out.behind.resize(pool_.size());
  int32_t k = 0;
  constexpr size_t kDist = 16;  // cells come at random: their head and span asked for ahead
  for (size_t j = 0, n = touched_.size(); j < n; ++j) {
    if (j + kDist < n) {
      __builtin_prefetch(&head_[touched_[j + kDist]]);
      __builtin_prefetch(&out.span[touched_[j + kDist]], 1);
    }
    const int32_t c = touched_[j];
    const int32_t first = k;
    for (int32_t i = head_[c]; i >= 0; i = pool_[i].next) out.behind[k++] = pool_[i].cell;
    out.span[c] = {first, k};
  }
}

void pair_pix_list(const ABuffer& abuf, int64_t pixel, double tie, std::vector<PixEntry>& scratch,
                   PnLists& pn, PairStats& stats) {
  if (abuf.head(pixel) < 0) return;
  // Read in place; copied to `scratch` only when a tie is reordered (rare).
  const PixEntry* e = abuf.begin(pixel);
  const size_t k = static_cast<size_t>(abuf.end(pixel) - e);
  ++stats.lists;
  stats.max_list = std::max<int64_t>(stats.max_list, static_cast<int64_t>(k));
  // Far to near: beyond the farthest entry the ray is outside the mesh, so the first entry
  // expected is back-facing.
  bool want_front = false;
  int32_t occluded = -1;  // cell of the last front-facing entry, while in a ray gap
  for (size_t i = 0; i < k; ++i) {
    if (e[i].front() != want_front) {
      size_t j = i + 1;
      while (j < k && e[j].t >= e[i].t - tie && e[j].front() != want_front) ++j;
      if (j < k && e[j].t >= e[i].t - tie) {
        if (e != scratch.data()) {
          scratch.assign(e, e + k);
          e = scratch.data();
        }
        std::rotate(scratch.begin() + i, scratch.begin() + j, scratch.begin() + j + 1);
        ++stats.tie_reorders;
      } else {
        ++stats.unpaired;  // taken as it is: the state follows the entry's own kind
      }
    }
    if (e[i].front()) {
      occluded = e[i].cell();
      want_front = false;
    } else {
      if (occluded >= 0) {
        const int32_t occluding = e[i].cell();
        ++stats.pairs;
        if (occluding == occluded) {
          ++stats.self_pairs;
        } else {
          pn.add(occluding, occluded);
        }
      }
      occluded = -1;
      want_front = true;
    }
  }
}

}  // namespace vob::sxmpvo
