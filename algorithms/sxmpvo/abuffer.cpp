#include "algorithms/sxmpvo/abuffer.h"

#include <algorithm>
#include <climits>

#include <immintrin.h>

#include "harness/cpu_features.h"

namespace vob::sxmpvo {

namespace {
constexpr int kLanes = 16;  // longest list ordered in AVX2 lanes
}  // namespace

void ABuffer::reset(int64_t pixels, int64_t first) {
  pixels_ = pixels;
  first_ = first;
  raw_.clear();
  batches_.clear();
  entries_ = 0;
  list_.clear();
  offsets_.assign(static_cast<size_t>(pixels) + 1, 0);
  head_insertions_ = walk_steps_ = lane_lists_ = 0;
}

void ABuffer::gather() {
  // Counting sort by pixel into the staged lists (each entry's rank parked in its `next`
  // until order() links them: one scatter of 16-byte entries). Each
  // pixel's count becomes its list's end, and the scatter counts it down to the list's
  // start: no cursor array to copy. A list comes out in reverse recording order, which
  // order() does not see (it replays the arrivals by rank). The count reads the keys
  // alone; the scatter takes item and rank from the entry's face.
  int32_t* end = offsets_.data();  // zero since reset(): gather() runs once a frame
  const int64_t first = first_;
  uint32_t rank_bits = 0;
  const auto count = [&](const RawBatch& raw) {
    const uint64_t* key = raw.key.data();
    for (size_t i = 0, n = raw.size; i < n; ++i) ++end[static_cast<int32_t>(static_cast<uint32_t>(key[i])) - first];
    for (const RawBatch::Face& f : raw.faces) rank_bits |= static_cast<uint32_t>(f.rank);
  };
  count(raw_);
  for (const RawBatch* b : batches_) count(*b);
  ranks_fit_ = rank_bits < (1u << 27);
  for (int64_t p = 1; p < pixels_; ++p) end[p] += end[p - 1];
  offsets_[pixels_] = static_cast<int32_t>(entries_);
  staged_.resize(static_cast<size_t>(entries_) + kLanes);  // lanes read 16 entries a list:
  std::fill(staged_.end() - kLanes, staged_.end(), PixEntry(0, 0, 0));  // past the last, set ones
  list_.resize(static_cast<size_t>(entries_) + kLanes);
  PixEntry* list = staged_.data();
  // Pixels come at random: the place of the entry kDist ahead is asked for before its
  // write (its list end may still move before then; a stale guess only costs a prefetch).
  constexpr size_t kDist = 32;
  const auto scatter = [&](const RawBatch& raw) {
    const size_t n = raw.size;
    const double* t = raw.t.data();
    const uint64_t* key = raw.key.data();
    const RawBatch::Face* face = raw.faces.data();
    const auto pixel = [&](size_t i) { return static_cast<int32_t>(static_cast<uint32_t>(key[i])) - first; };
    for (size_t i = 0; i < n; ++i) {
      if (i + kDist < n) __builtin_prefetch(&list[end[pixel(i + kDist)] - 1], 1);
      const RawBatch::Face& f = face[key[i] >> 32];
      list[--end[pixel(i)]] = {t[i], f.item, f.rank};
    }
  };
  scatter(raw_);
  for (const RawBatch* b : batches_) scatter(*b);
}

void ABuffer::order_scalar(int32_t b, int32_t e) {
  // By rank (short lists); then, in rank order, insertion one entry at a time into
  // increasing t, behind every entry not farther than itself (the mirror of "in front of
  // every entry farther than itself" in a decreasing list); then reversed. A new entry
  // passes the entries farther than it.
  PixEntry* in = list_.data() + b;
  std::copy(staged_.data() + b, staged_.data() + e, in);
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
  for (int32_t q = b; q < e; ++q) list_[q].next = q + 1 < e ? q + 1 : -1;
}

namespace {

// Lanes that take the larger key of a compare-exchange with their partner: kMax's bits.
template <int kMax>
__attribute__((target("avx2"), always_inline)) inline __m256i exchange(__m256i v, __m256i partner) {
  return _mm256_blend_epi32(_mm256_min_epi32(v, partner), _mm256_max_epi32(v, partner), kMax);
}
// Eight keys ascending: Batcher's bitonic network, lane i against lane i ^ j.
__attribute__((target("avx2"), always_inline)) inline __m256i sort8(__m256i v) {
  v = exchange<0x66>(v, _mm256_shuffle_epi32(v, 0xB1));
  v = exchange<0x3C>(v, _mm256_shuffle_epi32(v, 0x4E));
  v = exchange<0x5A>(v, _mm256_shuffle_epi32(v, 0xB1));
  v = exchange<0xF0>(v, _mm256_permute4x64_epi64(v, 0x4E));
  v = exchange<0xCC>(v, _mm256_shuffle_epi32(v, 0x4E));
  return exchange<0xAA>(v, _mm256_shuffle_epi32(v, 0xB1));
}
// A bitonic sequence of eight keys ascending.
__attribute__((target("avx2"), always_inline)) inline __m256i merge8(__m256i v) {
  v = exchange<0xF0>(v, _mm256_permute4x64_epi64(v, 0x4E));
  v = exchange<0xCC>(v, _mm256_shuffle_epi32(v, 0x4E));
  return exchange<0xAA>(v, _mm256_shuffle_epi32(v, 0xB1));
}
__attribute__((target("avx2"), always_inline)) inline __m256i reverse8(__m256i v) {
  return _mm256_permutevar8x32_epi32(v, _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0));
}
// The keys rank << 4 | place of entries [base, base + 8) below k (ranks read from `next`;
// the eight entries are read whole, past k too), the places from k on below every key.
__attribute__((target("avx2"), always_inline)) inline __m256i keys8(const PixEntry* in, int base, int k) {
  const float* f = reinterpret_cast<const float*>(in + base);  // `next` is each entry's 4th word
  const __m256 n01 = _mm256_loadu_ps(f), n23 = _mm256_loadu_ps(f + 8), n45 = _mm256_loadu_ps(f + 16),
               n67 = _mm256_loadu_ps(f + 24);
  const __m256 a = _mm256_shuffle_ps(n01, n23, _MM_SHUFFLE(3, 3, 3, 3));  // n0 n0 n2 n2 | n1 n1 n3 n3
  const __m256 b = _mm256_shuffle_ps(n45, n67, _MM_SHUFFLE(3, 3, 3, 3));  // n4 n4 n6 n6 | n5 n5 n7 n7
  const __m256i mixed = _mm256_castps_si256(_mm256_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0)));  // n0 n2 n4 n6 | n1 n3 n5 n7
  const __m256i rank = _mm256_permutevar8x32_epi32(mixed, _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
  const __m256i lane = _mm256_add_epi32(_mm256_set1_epi32(base), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
  const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(k), lane);
  return _mm256_blendv_epi8(_mm256_set1_epi32(INT32_MIN), _mm256_or_si256(_mm256_slli_epi32(rank, 4), lane), valid);
}

// One list of 2 to kW entries (kW = 8 or 16) into dst[0, kW) (entries from k on are left
// unset) in the order the scalar replay gives when every arrival is a head insertion:
// decreasing rank. Returns false when some arrival is not (t increasing somewhere along
// decreasing rank, or a NaN): then the scalar replay must order the list.
template <int kW>
__attribute__((target("avx2"))) bool order_lanes(const PixEntry* in, int k, int32_t first, PixEntry* dst) {
  alignas(32) int32_t place[16];
  if (kW == 8) {
    _mm256_store_si256(reinterpret_cast<__m256i*>(place), reverse8(sort8(keys8(in, 0, k))));
  } else {
    const __m256i a = sort8(keys8(in, 0, k)), b = reverse8(sort8(keys8(in, 8, k)));
    const __m256i lo = merge8(_mm256_min_epi32(a, b)), hi = merge8(_mm256_max_epi32(a, b));
    _mm256_store_si256(reinterpret_cast<__m256i*>(place), reverse8(hi));
    _mm256_store_si256(reinterpret_cast<__m256i*>(place + 8), reverse8(lo));
  }
  // Decreasing keys: the k entries first, by decreasing rank (invalid lanes read entry 0).
  __m128d t[kW + 1];
  for (int j = 0; j < kW; ++j) {
    __m128i e = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + (place[j] & 15)));
    t[j] = _mm_castsi128_pd(e);
    e = _mm_insert_epi32(e, first + j + 1, 3);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + j), e);
  }
  dst[k - 1].next = -1;
  t[kW] = t[kW - 1];
  // Every arrival a head insertion: t[j] >= t[j + 1] for j < k - 1 (false with a NaN).
  unsigned ok = 0;
  for (int j = 0; j < kW; j += 4) {
    const __m256d a = _mm256_set_m128d(_mm_unpacklo_pd(t[j + 2], t[j + 3]), _mm_unpacklo_pd(t[j], t[j + 1]));
    const __m256d b = _mm256_set_m128d(_mm_unpacklo_pd(t[j + 3], t[j + 4]), _mm_unpacklo_pd(t[j + 1], t[j + 2]));
    ok |= unsigned(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_GE_OQ))) << j;
  }
  const unsigned need = (1u << (k - 1)) - 1;
  return (ok & need) == need;
}

}  // namespace

void ABuffer::order(int64_t p0, int64_t p1) {
  const bool lanes = lanes_ && ranks_fit_ && cpu_has_avx2();
  // A list ordered in lanes is written 8 or 16 entries wide: past its end only over the
  // lists of [p0, p1) still to come (written after it), or the room after the last list;
  // where that is too short, through `tmp`. Most lists arrive in rank order = decreasing
  // depth (head insertions 99.98% on the helices): then the rank sort alone, in lanes,
  // gives the list without the scalar sort's mispredicted loop exits (5.2-5.7 ns an entry
  // against 3.1-3.2, BM_ABufferOrder); any other list takes the scalar replay.
  const int32_t limit = p1 == pixels_ ? static_cast<int32_t>(entries_ + kLanes) : offsets_[p1];
  PixEntry* list = list_.data();
  for (int64_t p = p0; p < p1; ++p) {
    if (p + 8 <= p1 && offsets_[p] == offsets_[p + 8]) {  // eight empty lists at once (most are empty)
      p += 7;
      continue;
    }
    const int32_t b = offsets_[p], e = offsets_[p + 1];
    const int32_t k = e - b;
    if (k == 0) continue;
    if (k == 2 && lanes_) {  // two arrivals: the replay is one compare (most lists of larger faces: zoo, tet-hand)
      const PixEntry& x = staged_[b];
      const PixEntry& y = staged_[b + 1];
      const bool x_first = x.next < y.next;  // by rank
      const PixEntry& first = x_first ? x : y;
      const PixEntry& later = x_first ? y : x;
      const bool behind = first.t > later.t;  // the later arrival walks past the first
      const PixEntry& far = behind ? first : later;
      const PixEntry& near = behind ? later : first;
      list[b] = PixEntry(far.t, far.item, b + 1);
      list[b + 1] = PixEntry(near.t, near.item, -1);
      head_insertions_ += behind ? 1 : 2;
      walk_steps_ += behind ? 1 : 0;
      ++lane_lists_;
      continue;
    }
    if (lanes && k >= 2 && k <= kLanes) {
      const int w = k <= 8 ? 8 : 16;
      PixEntry tmp[kLanes];
      PixEntry* dst = b + w <= limit ? list + b : tmp;
      const bool done = w == 8 ? order_lanes<8>(staged_.data() + b, k, b, dst)
                               : order_lanes<16>(staged_.data() + b, k, b, dst);
      if (done) {
        if (dst == tmp) std::copy(tmp, tmp + k, list + b);
        head_insertions_ += k;
        ++lane_lists_;
        continue;
      }
    }
    order_scalar(b, e);
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

}  // namespace vob::sxmpvo
