#include "harness/sort/radix_argsort.h"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdlib>
#include <new>
#include <numeric>

#include "harness/huge_mapping.h"

namespace vob {
namespace {

// At most 11-bit digits (so at most 3 passes): 2048 counters (8 KB) stay in L1. Measured on
// 1M view depths (a 23-24-bit range): 3 passes of 8 bits ~ 3 of 11 < 2 of 12, whose 4096
// write streams per pass thrash the caches.
constexpr int kMaxDigitBits = 11;
constexpr size_t kMinBlock = size_t(1) << 15;  // below this a block is not worth a task
// Ranges of more than two digits: one scatter by the bits above the low kLowBits into
// buckets, then each bucket sorted in cache by its low bits (two 8-bit passes), so the keys
// cross memory twice instead of three times (profile of 1M view depths, 24 bits: the three
// scatters were 2/3 of the centroid frame). Kept while the top digit has <= kMaxDigitBits.
constexpr int kLowBits = 16;
// One thread's fused key pass (rooms): 15 low bits, so a 24-bit range of 1M view depths
// scatters into 512 rooms of about 2k words, each sorted in L1. The best count depends on
// the host: on an AMD EPYC (session 27) 17 bits, 128 rooms, were fastest (512 rooms 6-25%
// slower a frame, 256 1-7% slower); on an Intel Xeon (48 KiB L1, 2 MiB L2; session 50) 512
// rooms gave frames about 5% shorter than 128, in both the key pass and the rooms' sorts.
constexpr int kRoomLowBits = 15;
static_assert(kRoomLowBits + RadixArgsort::kChunkBits == 32, "a room word: low key bits and id in chunk");
constexpr size_t kSmallBucket = 48;  // below this a bucket is insertion sorted
// Ranges of 17 to 22 bits (two 11-bit digits) take the two-level path too from this many
// keys on: their two scatters of 2^11 write streams each through memory cost more than one
// scatter of 2^kTopBits and the buckets in cache (view 1 of the 1M helix, all depths in one
// binade of float: 22 bits, its sort 7.0-8.2 ms against 4.2-4.5 ms on the two-level path).
constexpr size_t kTwoLevelMinKeys = size_t(1) << 17;
constexpr int kTopBits = 7;  // the two-level path's smallest top digit (23 bits: as before)
// One thread's rooms take the fewest top bits the room word allows (the range's bits less
// kRoomLowBits), at least 5: 32 rooms. (Session 30, AMD, 17 low bits: a 22-bit range, view
// 1 of the 3-view 1M helix, went from 128 rooms to 32 with frame minima 3-6% lower.)
constexpr int kRoomTopBits = 5;

// Counts of each of the first kPasses digits of (key - mn): table p at c + p * radix.
// Neighbouring cells have near keys, so consecutive increments hit one counter; two sets of
// counters (even and odd elements) halve that store-to-load chain.
template <int kPasses>
void count(const uint32_t* k, size_t n, uint32_t mn, int width, uint32_t mask, size_t radix, uint32_t* c) {
  uint32_t* c2 = c + kPasses * radix;
  size_t i = 0;
  for (; i + 1 < n; i += 2) {
    const uint32_t v = k[i] - mn, w = k[i + 1] - mn;
    for (int p = 0; p < kPasses; ++p) {
      ++c[size_t(p) * radix + ((v >> (p * width)) & mask)];
      ++c2[size_t(p) * radix + ((w >> (p * width)) & mask)];
    }
  }
  if (i < n)
    for (int p = 0; p < kPasses; ++p) ++c[size_t(p) * radix + (((k[i] - mn) >> (p * width)) & mask)];
  for (size_t j = 0; j < kPasses * radix; ++j) c[j] += c2[j];
}

uint64_t* pairs(const HugeWords& w) { return reinterpret_cast<uint64_t*>(w.data()); }

// Inserts pair p (key << 32 | id) into the sorted a[0..i), after the pairs of equal key
// (stable): the small buckets' sort.
inline void insert_by_key(uint64_t* a, size_t i, uint64_t p) {
  for (; i > 0 && (a[i - 1] >> 32) > (p >> 32); --i) a[i] = a[i - 1];
  a[i] = p;
}

// Both digit counts turned into starting slots, over digits 0..last (the low digit's
// range, which holds the high digit's).
inline void exclusive_prefix(uint32_t* c0, uint32_t* c1, uint32_t last) {
  uint32_t s0 = 0, s1 = 0;
  for (uint32_t d = 0; d <= last; ++d) {
    const uint32_t a = c0[d], b = c1[d];
    c0[d] = s0, c1[d] = s1;
    s0 += a, s1 += b;
  }
}

// The ids (low words) of the first m pairs of a.
inline void write_ids(const uint64_t* a, size_t m, int32_t* out) {
  for (size_t i = 0; i < m; ++i) out[i] = static_cast<int32_t>(static_cast<uint32_t>(a[i]));
}

// One scatter pass over [lo, hi): `off` holds the block's next slot per digit. Between
// passes a key and its id travel as one 64-bit word (key high): one write stream per digit,
// not two. The first pass reads the bare keys (the id is the index), the last writes ids.
template <bool kFirst, bool kLast>
void scatter(const uint32_t* k, const uint64_t* sp, uint64_t* dp, int32_t* out, size_t lo, size_t hi,
             uint32_t mn, int shift, uint32_t mask, uint32_t* off) {
  for (size_t i = lo; i < hi; ++i) {
    const uint64_t p = kFirst ? (uint64_t(k[i]) << 32) | uint32_t(i) : sp[i];
    const uint32_t x = static_cast<uint32_t>(p >> 32);
    const uint32_t pos = off[((x - mn) >> shift) & mask]++;
    if (kLast) out[pos] = static_cast<int32_t>(static_cast<uint32_t>(p));
    else dp[pos] = p;
  }
}

// Sorts the m pairs of one bucket (key << 32 | id, in id order within equal keys) by their
// low `low` bits (<= kRoomLowBits) of (key - mn), stably, in two passes, and writes their ids.
void sort_bucket(const uint64_t* src, size_t m, uint32_t mn, int low, int32_t* out, std::vector<uint64_t>& tmp) {
  if (m < kSmallBucket) {
    uint64_t a[kSmallBucket];
    for (size_t i = 0; i < m; ++i) insert_by_key(a, i, src[i]);
    write_ids(a, m, out);
    return;
  }
  const int w0 = (low + 1) / 2;
  const uint32_t m0 = (1u << w0) - 1, m1 = (1u << (low - w0)) - 1;
  uint32_t c0[512] = {}, c1[512] = {};  // up to 9 + 8 bits (kRoomLowBits)
  for (size_t i = 0; i < m; ++i) {
    const uint32_t x = static_cast<uint32_t>(src[i] >> 32) - mn;
    ++c0[x & m0];
    ++c1[(x >> w0) & m1];
  }
  exclusive_prefix(c0, c1, m0);
  if (tmp.size() < m) tmp.resize(m);
  for (size_t i = 0; i < m; ++i) tmp[c0[(static_cast<uint32_t>(src[i] >> 32) - mn) & m0]++] = src[i];
  for (size_t i = 0; i < m; ++i) {
    const uint64_t p = tmp[i];
    out[c1[((static_cast<uint32_t>(p >> 32) - mn) >> w0) & m1]++] = static_cast<int32_t>(static_cast<uint32_t>(p));
  }
}

// Sorts one room of the fused key pass by the low `low` (<= kRoomLowBits) bits of (key - mn),
// stably, in two passes, and writes its ids to out[0..m). Its words (low key bits <<
// kChunkBits | id within its chunk) lie in segments by chunk of ids: chunk j's end at ends[j * stride] (the
// first begins at `begin`); within a segment they are in id order.
void sort_room_bucket(const uint32_t* w, size_t begin, size_t m, const uint32_t* ends, size_t stride,
                 size_t nchunks, int low, int32_t* out, std::vector<uint64_t>& tmp) {
  constexpr int kBits = RadixArgsort::kChunkBits;
  constexpr uint32_t kMask = (uint32_t(1) << kBits) - 1;
  // Each segment's words as (key bits << 32 | id) pairs, in id order.
  const auto each = [&](auto&& f) {
    size_t s = begin;
    for (size_t j = 0; j < nchunks; ++j) {
      const size_t e = ends[j * stride];
      const uint32_t hi = static_cast<uint32_t>(j) << kBits;
      for (size_t i = s; i < e; ++i) f((uint64_t(w[i] >> kBits) << 32) | (hi | (w[i] & kMask)));
      s = e;
    }
  };
  if (m < kSmallBucket) {
    uint64_t a[kSmallBucket];
    size_t i = 0;
    each([&](uint64_t p) { insert_by_key(a, i++, p); });
    write_ids(a, m, out);
    return;
  }
  const int w0 = (low + 1) / 2;
  const uint32_t m0 = (1u << w0) - 1, m1 = (1u << (low - w0)) - 1;
  // The high digit in two counter sets (even and odd words): neighbouring cells in a room
  // often share it, and one set would chain each increment on the last one's store.
  uint32_t c0[512] = {}, c1[512] = {}, c2[512] = {};  // up to 9 + 8 bits (kRoomLowBits)
  size_t i = begin;
  for (; i + 1 < begin + m; i += 2) {
    const uint32_t x = w[i] >> kBits, y = w[i + 1] >> kBits;
    ++c0[x & m0];
    ++c1[(x >> w0) & m1];
    ++c0[y & m0];
    ++c2[(y >> w0) & m1];
  }
  if (i < begin + m) {
    const uint32_t x = w[i] >> kBits;
    ++c0[x & m0];
    ++c1[(x >> w0) & m1];
  }
  for (uint32_t d = 0; d <= m1; ++d) c1[d] += c2[d];
  exclusive_prefix(c0, c1, m0);
  if (tmp.size() < m) tmp.resize(m);
  if ((nchunks << kBits) <= (size_t(1) << 24) && low - w0 <= 8) {
    // Ids below 2^24: between the passes the high digit and the id share a 32-bit word,
    // so the room's in-cache buffer is half the size.
    uint32_t* t = reinterpret_cast<uint32_t*>(tmp.data());
    size_t s = begin;
    for (size_t j = 0; j < nchunks; ++j) {
      const size_t e = ends[j * stride];
      const uint32_t hi = static_cast<uint32_t>(j) << kBits;
      for (size_t i = s; i < e; ++i) {
        const uint32_t x = w[i] >> kBits;
        t[c0[x & m0]++] = (x >> w0) << 24 | hi | (w[i] & kMask);
      }
      s = e;
    }
    for (size_t i = 0; i < m; ++i) out[c1[t[i] >> 24]++] = static_cast<int32_t>(t[i] & 0xffffffu);
    return;
  }
  each([&](uint64_t p) { tmp[c0[static_cast<uint32_t>(p >> 32) & m0]++] = p; });
  for (size_t i = 0; i < m; ++i) {
    const uint64_t p = tmp[i];
    out[c1[(static_cast<uint32_t>(p >> 32) >> w0) & m1]++] = static_cast<int32_t>(static_cast<uint32_t>(p));
  }
}

}  // namespace

void HugeWords::Free::operator()(uint32_t* p) const { unmap_huge(p, bytes); }

void HugeWords::reserve(size_t n) {
  if (n <= cap_) return;
  const size_t bytes = (n * 4 + kHugeMappingAlign - 1) / kHugeMappingAlign * kHugeMappingAlign;
  words_.reset();
  cap_ = 0;
  uint32_t* p = static_cast<uint32_t*>(map_huge(bytes));
  if (!p) throw std::bad_alloc();
  words_ = std::unique_ptr<uint32_t, Free>(p, Free{bytes});
  cap_ = bytes / 4;
}

void RadixArgsort::plan(size_t n) {
  n_ = n;
  const int limit = static_cast<int>(std::min<size_t>(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
      static_cast<size_t>(tbb::this_task_arena::max_concurrency())));
  // A few blocks per thread so that a thread slowed by a neighbour's load is covered.
  nblocks_ = limit <= 1 ? 1 : std::max<size_t>(1, std::min<size_t>(size_t(limit) * 4, n / kMinBlock));
  keys_.reserve(n);
  block_min_.assign(nblocks_, 0);
  block_max_.assign(nblocks_, 0);
}

bool RadixArgsort::plan_counts(uint32_t lo, uint32_t hi) {
  pre_ = false;
  if (lo > hi || n_ < kTwoLevelMinKeys) return false;
  const uint32_t range = hi - lo;
  const int bits = range == 0 ? 0 : 32 - __builtin_clz(range);
  if (bits <= kLowBits || bits - kLowBits > kMaxDigitBits) return false;
  const int top = nblocks_ == 1 ? std::max(bits - kRoomLowBits, kRoomTopBits) : std::max(bits - kLowBits, kTopBits);
  pre_lo_ = lo, pre_hi_ = hi, pre_bits_ = bits;
  pre_shift_ = bits - top;
  pre_mask_ = (uint32_t(1) << top) - 1;
  counts_.assign(2 * nblocks_ * (size_t(pre_mask_) + 1), 0);
  if (nblocks_ == 1) room_.assign(size_t(pre_mask_) + 2, 0);  // the sample's counts
  return pre_ = true;
}

void RadixArgsort::plan_room() {
  // A bucket's count is about kSample times its sample's count c; runs of neighbouring
  // cells make the estimate err by a few runs, and independent keys by about sqrt(c)
  // samples (binomial), which in small buckets is more than a quarter: so the larger of a
  // quarter more and five standard errors more, two samples' worth and a quarter of an
  // average bucket (too little: the key pass starts over, costing time, not order).
  const size_t radix = size_t(pre_mask_) + 1;
  const size_t nchunks = (n_ + (size_t(1) << kChunkBits) - 1) >> kChunkBits;
  next_.resize(radix);
  const uint32_t slack = static_cast<uint32_t>(2 * kSample + n_ / (4 * radix));
  uint32_t sum = 0;
  for (size_t d = 0; d < radix; ++d) {
    const uint32_t c = room_[d];
    const uint32_t more = std::max(c / 4, static_cast<uint32_t>(5 * std::sqrt(double(c))) + 1);
    const uint32_t size = (c + more) * kSample + slack;
    room_[d] = sum;
    next_[d] = uint64_t(size) << 32 | sum;
    sum += size;
  }
  room_[radix] = sum;
  pairs_.reserve(sum);
  ends_.resize(nchunks * radix);
}

void RadixArgsort::sort_rooms(int32_t* out) {
  const size_t radix = size_t(pre_mask_) + 1;
  const size_t nc = (n_ + (size_t(1) << kChunkBits) - 1) >> kChunkBits;
  passes_ = 3;
  used_pre_ = true;
  thread_local std::vector<uint64_t> tmp;
  size_t at = 0;
  for (size_t d = 0; d < radix; ++d) {
    const size_t m = static_cast<uint32_t>(next_[d]) - room_[d];
    sort_room_bucket(pairs_.data(), room_[d], m, ends_.data() + d, radix, nc, pre_shift_, out + at, tmp);
    at += m;
  }
}

void RadixArgsort::sort_keys(int32_t* out) {
  const size_t n = n_;
  passes_ = 0;
  used_pre_ = false;
  if (n == 0) return;
  if (fused_) {
    sort_rooms(out);
    return;
  }
  const uint32_t mn = *std::min_element(block_min_.begin(), block_min_.end());
  const uint32_t mx = *std::max_element(block_max_.begin(), block_max_.end());
  if (pre_ && mn >= pre_lo_ && mx <= pre_hi_) {  // every key inside the guess: its counts hold
    used_pre_ = true;
    sort_two_level(out, pre_lo_, pre_bits_, pre_bits_ - pre_shift_, true);
    return;
  }
  const uint32_t range = mx - mn;
  const int bits = range == 0 ? 0 : 32 - __builtin_clz(range);
  if (bits == 0) {  // one key everywhere: the input order stays
    std::iota(out, out + n, 0);
    return;
  }
  const int np = (bits + kMaxDigitBits - 1) / kMaxDigitBits;
  if (bits > kLowBits && bits - kLowBits <= kMaxDigitBits && (np >= 3 || n >= kTwoLevelMinKeys)) {
    // The top digit: the bits above kLowBits, at least kTopBits (few write streams; bits
    // > kLowBits leaves a low part of 10 bits or more).
    sort_two_level(out, mn, bits, std::max(bits - kLowBits, kTopBits), false);
    return;
  }
  const int width = (bits + np - 1) / np;
  const size_t radix = size_t(1) << width;
  const uint32_t mask = static_cast<uint32_t>(radix - 1);
  passes_ = np;
  if (np >= 2) pairs_.reserve(2 * n);
  if (np >= 3) pairs2_.reserve(2 * n);

  const bool serial = nblocks_ == 1;
  // One block: every digit's counts in one read of the keys. Several: per pass, per block.
  counts_.assign((serial ? 2 * size_t(np) : nblocks_) * radix, 0);
  if (serial) {
    const uint32_t* k = keys_.data();
    uint32_t* c = counts_.data();
    if (np == 1) count<1>(k, n, mn, width, mask, radix, c);
    else if (np == 2) count<2>(k, n, mn, width, mask, radix, c);
    else count<3>(k, n, mn, width, mask, radix, c);
  }
  const uint32_t* k = keys_.data();
  for (int q = 0; q < np; ++q) {
    const int shift = q * width;
    const uint64_t* sp = (q % 2 == 1) ? pairs(pairs_) : pairs(pairs2_);  // unused when q == 0
    uint64_t* dp = (q % 2 == 0) ? pairs(pairs_) : pairs(pairs2_);
    const bool last = q + 1 == np;
    uint32_t* table = serial ? counts_.data() + size_t(q) * radix : counts_.data();
    if (!serial) {
      std::fill(counts_.begin(), counts_.end(), 0u);
      for_blocks([&](size_t b, size_t lo, size_t hi) {
        uint32_t* c = table + b * radix;
        if (q == 0)
          for (size_t i = lo; i < hi; ++i) ++c[((k[i] - mn) >> shift) & mask];
        else
          for (size_t i = lo; i < hi; ++i) ++c[((static_cast<uint32_t>(sp[i] >> 32) - mn) >> shift) & mask];
      });
    }
    // Exclusive prefix over (digit, block): block b's slots for a digit follow block b-1's.
    uint32_t sum = 0;
    const size_t nb = serial ? 1 : nblocks_;
    for (size_t d = 0; d < radix; ++d)
      for (size_t b = 0; b < nb; ++b) {
        const uint32_t c = table[b * radix + d];
        table[b * radix + d] = sum;
        sum += c;
      }
    for_blocks([&](size_t b, size_t lo, size_t hi) {
      uint32_t* off = table + (serial ? 0 : b * radix);
      if (q == 0 && last) scatter<true, true>(k, sp, dp, out, lo, hi, mn, shift, mask, off);
      else if (q == 0) scatter<true, false>(k, sp, dp, out, lo, hi, mn, shift, mask, off);
      else if (last) scatter<false, true>(k, sp, dp, out, lo, hi, mn, shift, mask, off);
      else scatter<false, false>(k, sp, dp, out, lo, hi, mn, shift, mask, off);
    });
  }
}

void RadixArgsort::sort_two_level(int32_t* out, uint32_t mn, int bits, int top, bool counted) {
  const size_t n = n_;
  const int shift = bits - top;
  const size_t radix = size_t(1) << top;
  const uint32_t mask = static_cast<uint32_t>(radix - 1);
  passes_ = 3;  // one scatter through memory, two in cache
  pairs_.reserve(2 * n);
  const size_t nb = nblocks_;
  const uint32_t* k = keys_.data();
  if (!counted) {
    counts_.assign(2 * nb * radix, 0);
    for_blocks([&](size_t b, size_t lo, size_t hi) {
      // Two counter sets (even and odd elements): neighbouring cells share a bucket.
      uint32_t *c = counts_.data() + b * radix, *c2 = counts_.data() + (nb + b) * radix;
      size_t i = lo;
      for (; i + 1 < hi; i += 2) {
        ++c[((k[i] - mn) >> shift) & mask];
        ++c2[((k[i + 1] - mn) >> shift) & mask];
      }
      if (i < hi) ++c[((k[i] - mn) >> shift) & mask];
      for (size_t d = 0; d < radix; ++d) c[d] += c2[d];
    });
  }
  // Exclusive prefix over (bucket, block); a bucket starts at its block 0 slot.
  bucket_start_.resize(radix + 1);
  uint32_t sum = 0;
  for (size_t d = 0; d < radix; ++d) {
    bucket_start_[d] = sum;
    for (size_t b = 0; b < nb; ++b) {
      const uint32_t c = counts_[b * radix + d];
      counts_[b * radix + d] = sum;
      sum += c;
    }
  }
  bucket_start_[radix] = sum;
  uint64_t* dp = pairs(pairs_);
  for_blocks([&](size_t b, size_t lo, size_t hi) {
    scatter<true, false>(k, nullptr, dp, out, lo, hi, mn, shift, mask, counts_.data() + b * radix);
  });
  const auto buckets = [&](size_t d0, size_t d1) {
    thread_local std::vector<uint64_t> tmp;
    for (size_t d = d0; d < d1; ++d)
      sort_bucket(dp + bucket_start_[d], bucket_start_[d + 1] - bucket_start_[d], mn, shift, out + bucket_start_[d], tmp);
  };
  if (nb == 1) {
    buckets(0, radix);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, radix, 8),
                    [&](const tbb::blocked_range<size_t>& r) { buckets(r.begin(), r.end()); });
}

}  // namespace vob
