// Stable argsort of uint32 keys made on the fly: the key pass writes the keys and their
// range in one streamed pass; an LSD radix sort then runs over only the bits in which the
// keys differ (key - min, digits of <= 11 bits: a 22-bit range takes 2 passes), the ids
// 0..n-1 made in the first scatter and the last pass writing the caller's output (no key
// transform pass, no keys written back, no copy). Ranges of 23 to 27 bits (1M view depths
// of a mesh span ~24) take one scatter by their top bits (at least 7) and then sort each
// bucket by its low (at most 16; one thread's fused key pass 15) bits in cache: two trips
// through memory instead of three;
// so do ranges of 17 to 22 bits from 2^17 keys on, instead of two 11-bit scatters.
// Blocks run in parallel with TBB when the global thread limit allows; per-block counts keep
// it stable, so the order never depends on the thread count.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <climits>
#include <memory>
#include <vector>

namespace vob {

// A buffer of 32-bit words on transparent huge pages where the kernel offers them (madvise;
// a mapping of its own, harness/huge_mapping.h): a scatter over 4 MB with thousands of write
// streams otherwise misses the TLB on most stores.
class HugeWords {
 public:
  void reserve(size_t n);  // grows only; contents are not kept
  uint32_t* data() const { return words_.get(); }
  size_t capacity() const { return cap_; }

 private:
  struct Free {
    size_t bytes;  // of the mapping (no initializer here: GCC then thinks Free not default-constructible)
    void operator()(uint32_t* p) const;
  };
  std::unique_ptr<uint32_t, Free> words_;
  size_t cap_ = 0;
};

class RadixArgsort {
 public:
  // out[0..n) = ids sorted by ascending key_of(id), ties by id. key_of(i) must be safe to
  // call from several threads at once.
  template <class KeyOf>
  void sort(size_t n, KeyOf&& key_of, int32_t* out) {
    make_keys(n, key_of);
    sort_keys(out);
  }

  // The two halves of sort(), apart so that callers can time them as phases. [lo, hi] is
  // an optional guess of the keys' range (lo > hi: none): when it asks for the two-level
  // path, the key pass also counts its top digit against lo, saving sort_keys a read of the
  // keys. sort_keys uses those counts only if every key fell inside; the order is the same
  // either way (a stable sort by more bits than needed is the same permutation).
  // With one block the key pass goes further: it scatters each key's word straight into
  // its top-digit bucket, into room sized from a sample of every kSample-th key (the keys
  // are then never written; sort_keys only sorts the buckets). If a bucket's room runs out
  // or a key falls outside the guess, it starts over as above (same order either way).
  template <class KeyOf>
  void make_keys(size_t n, KeyOf&& key_of, uint32_t lo = 1, uint32_t hi = 0) {
    // Keys a run at a time into L1 (a plain loop the compiler vectorises), then scattered.
    const auto keys_of = [&](size_t i0, size_t i1, uint32_t* k) {
      for (size_t i = i0; i < i1; ++i) k[i - i0] = key_of(i);
    };
    make_keys_by_runs(n, key_of, keys_of, [&](size_t j) { return key_of(j * kSample); }, lo, hi);
  }

  // make_keys, with the fused key pass's keys made by keys_of(i0, i1, k) (k[i - i0] =
  // key_of(i), up to kRun at a time) and its sample by sample_of(j) = key_of(j * kSample),
  // e.g. from a compact copy of every kSample-th item (a strided read of the items costs a
  // cache miss a sample when they are not in cache).
  static constexpr size_t kSample = 32;  // the fused key pass sizes its buckets from every 32nd key
  // The fused key pass's ids travel as 17 bits within a chunk of 2^17 ids, beside the
  // key's low (<= 15) bits: one 32-bit word per key through memory, not a 64-bit pair.
  static constexpr int kChunkBits = 17;
  template <class KeyOf, class KeysOf, class SampleOf>
  void make_keys_by_runs(size_t n, KeyOf&& key_of, KeysOf&& keys_of, SampleOf&& sample_of, uint32_t lo, uint32_t hi) {
    plan(n);
    const bool pre = plan_counts(lo, hi);
    fused_ = false;
    if (pre && nblocks_ == 1) {
      for (size_t j = 0; j * kSample < n; ++j) ++room_[((sample_of(j) - pre_lo_) >> pre_shift_) & pre_mask_];
      plan_room();
      if ((fused_ = scatter_keys(n, keys_of))) return;
    }
    const int shift = pre_shift_;
    const uint32_t mask = pre_mask_, base = pre_lo_;
    const size_t radix = size_t(mask) + 1, nb = nblocks_;
    for_blocks([&](size_t b, size_t lo_i, size_t hi_i) {
      uint32_t* k = keys_.data();
      // The range as signed ints (x with its top bit flipped): SSE2 vectorises signed
      // min/max, not unsigned.
      int32_t mn = INT32_MAX, mx = INT32_MIN;
      const auto one = [&](size_t i) {
        const uint32_t x = key_of(i);
        k[i] = x;
        const int32_t y = static_cast<int32_t>(x ^ 0x80000000u);
        mn = std::min(mn, y);
        mx = std::max(mx, y);
        return x;
      };
      if (pre) {
        // Two counter sets (even and odd elements): neighbouring cells share a bucket.
        uint32_t *c = counts_.data() + b * radix, *c2 = counts_.data() + (nb + b) * radix;
        size_t i = lo_i;
        for (; i + 1 < hi_i; i += 2) {
          ++c[((one(i) - base) >> shift) & mask];
          ++c2[((one(i + 1) - base) >> shift) & mask];
        }
        if (i < hi_i) ++c[((one(i) - base) >> shift) & mask];
        for (size_t d = 0; d < radix; ++d) c[d] += c2[d];
      } else {
        for (size_t i = lo_i; i < hi_i; ++i) one(i);
      }
      block_min_[b] = static_cast<uint32_t>(mn) ^ 0x80000000u;
      block_max_[b] = static_cast<uint32_t>(mx) ^ 0x80000000u;
    });
  }
  void sort_keys(int32_t* out);  // out[0..n) for the n of make_keys

  int passes() const { return passes_; }  // radix passes of the last sort (0: all keys equal)
  bool counted_in_key_pass() const { return used_pre_; }  // the last sort used the key pass's counts
  bool scattered_in_key_pass() const { return fused_; }  // ... and its scatter into buckets
  int blocks() const { return static_cast<int>(nblocks_); }
  size_t bytes() const {
    return (keys_.capacity() + pairs_.capacity() + pairs2_.capacity()) * 4 +
           (counts_.capacity() + room_.capacity() + ends_.capacity()) * 4 + next_.capacity() * 8;
  }

 private:
  void plan(size_t n);         // sizes the buffers, picks the blocks from the thread limit
  // Ranges of 17 to 27 bits: one scatter by the `top` bits, then each bucket in cache;
  // `counted`: counts_ already holds the top digit's counts (from the key pass).
  void sort_two_level(int32_t* out, uint32_t mn, int bits, int top, bool counted);
  // From the guessed range [lo, hi]: whether the key pass counts the top digit (then
  // counts_ is zeroed and pre_* set).
  bool plan_counts(uint32_t lo, uint32_t hi);
  static constexpr size_t kRun = 256;     // keys made at a time by the fused key pass
  // From the sampled counts in room_: each bucket's room (room_[d], room_[d + 1]) in pairs_
  // (an estimate with slack) and next_ = each room's size << 32 | its start.
  void plan_room();
  void sort_rooms(int32_t* out);  // sort_keys after a fused key pass

  // The fused key pass: each key's word (low bits << kChunkBits | id within its chunk) into its
  // bucket's room; after each chunk its slots go to ends_ (each segment's end). False if a
  // room was full or a key outside [pre_lo_, pre_hi_].
  template <class KeysOf>
  bool scatter_keys(size_t n, KeysOf& keys_of) {
    const uint32_t base = pre_lo_, range = pre_hi_ - pre_lo_, low_mask = (uint32_t(1) << pre_shift_) - 1;
    constexpr uint32_t kChunkMask = (uint32_t(1) << kChunkBits) - 1;
    const int shift = pre_shift_;
    const size_t radix = size_t(pre_mask_) + 1;
    uint32_t* w = pairs_.data();
    // Per bucket one word, (room left << 32 | next slot): one load tells both where the key
    // goes and whether its room is full (< 2^32), not a second load of the room's end.
    uint64_t* next = next_.data();
    uint32_t run[kRun];
    // (The slot kept in a register along runs of one bucket loses: on view 1 of the 1M helix
    // 60% of neighbouring cells change bucket, and the branch mispredicts.)
    for (size_t i0 = 0, j = 0; i0 < n; i0 += size_t(1) << kChunkBits, ++j) {
      const size_t i1 = std::min(n, i0 + (size_t(1) << kChunkBits));
      for (size_t r0 = i0; r0 < i1; r0 += kRun) {
        const size_t r1 = std::min(i1, r0 + kRun);
        keys_of(r0, r1, run);
        for (size_t i = r0; i < r1; ++i) {
          const uint32_t v = run[i - r0] - base;
          const uint32_t d = v >> shift;
          if (v > range) return false;  // (before d indexes next: d may be past the rooms)
          const uint64_t p = next[d];
          if (p < (uint64_t(1) << 32)) return false;
          w[static_cast<uint32_t>(p)] = (v & low_mask) << kChunkBits | static_cast<uint32_t>(i & kChunkMask);
          next[d] = p + 1 - (uint64_t(1) << 32);
        }
      }
      for (size_t d = 0; d < radix; ++d) ends_[j * radix + d] = static_cast<uint32_t>(next[d]);
    }
    return true;
  }

  template <class F>
  void for_blocks(F&& f) {
    const auto run = [&](size_t b) { f(b, block_begin(b), block_begin(b + 1)); };
    if (nblocks_ == 1) {
      run(0);
      return;
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, nblocks_, 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t b = r.begin(); b != r.end(); ++b) run(b);
    });
  }
  size_t block_begin(size_t b) const { return n_ * b / nblocks_; }

  size_t n_ = 0, nblocks_ = 1;
  int passes_ = 0;
  bool pre_ = false, used_pre_ = false, fused_ = false;  // the key pass counted the top digit of (key - pre_lo_) >> pre_shift_
  uint32_t pre_lo_ = 0, pre_hi_ = 0, pre_mask_ = 0;
  int pre_bits_ = 0, pre_shift_ = 0;
  HugeWords keys_, pairs_, pairs2_;  // (key << 32 | id) pairs, two words each; or the fused pass's rooms
  std::vector<uint32_t> block_min_, block_max_;
  std::vector<uint32_t> counts_;  // nblocks x radix: counts, then each block's next slot
  std::vector<uint32_t> bucket_start_;  // sort_two_level: each top-digit bucket's first slot
  std::vector<uint32_t> room_, ends_;  // the fused key pass: rooms, segment ends
  std::vector<uint64_t> next_;         // ... and per room (room left << 32 | next slot)
};

}  // namespace vob
