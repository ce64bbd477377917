#include "harness/sort/radix_sort.h"

#include <algorithm>

namespace vob {

void radix_sort_by_key(std::vector<float>& keys, std::vector<int32_t>& values, std::vector<uint64_t>& scratch) {
  const size_t n = keys.size();
  if (n == 0) return;
  // Each pair moves as one word (sortable key << 32 | value): one store a move, one array
  // of write streams instead of two; three 11-bit passes instead of four 8-bit ones
  // (measured against that: docs/design-notes.md, session 49).
  constexpr int kBits = 11;
  constexpr uint32_t kMask = (1u << kBits) - 1;
  if (scratch.size() < 2 * n) scratch.resize(2 * n);
  uint64_t* src = scratch.data();
  uint64_t* dst = src + n;
  // One pass makes the words and counts all three digits.
  uint32_t hist[3][1u << kBits] = {};
  uint32_t *h0 = hist[0], *h1 = hist[1], *h2 = hist[2];
  for (size_t i = 0; i < n; ++i) {
    const uint32_t x = float_sort_key(keys[i]);
    src[i] = (uint64_t(x) << 32) | static_cast<uint32_t>(values[i]);
    ++h0[x & kMask];
    ++h1[(x >> kBits) & kMask];
    ++h2[x >> (2 * kBits)];
  }
  for (int pass = 0; pass < 3; ++pass) {
    uint32_t* h = hist[pass];
    const int shift = 32 + kBits * pass;
    if (h[(src[0] >> shift) & kMask] == n) continue;  // the digit is constant
    uint32_t sum = 0;
    for (uint32_t d = 0; d <= kMask; ++d) {
      const uint32_t c = h[d];
      h[d] = sum;
      sum += c;
    }
    for (size_t i = 0; i < n; ++i) {
      const uint64_t w = src[i];
      dst[h[(w >> shift) & kMask]++] = w;
    }
    std::swap(src, dst);
  }
  // Keys back to floats (inverse transform) and the values, in sorted order.
  for (size_t i = 0; i < n; ++i) {
    uint32_t u = static_cast<uint32_t>(src[i] >> 32);
    u = (u & 0x80000000u) ? (u & 0x7fffffffu) : ~u;
    std::memcpy(&keys[i], &u, 4);
    values[i] = static_cast<int32_t>(static_cast<uint32_t>(src[i]));
  }
}

void radix_sort_by_key64(std::vector<double>& keys, std::vector<int32_t>& values, Radix64Scratch& scratch) {
  const size_t n = keys.size();
  std::vector<uint64_t>&k = scratch.keys, &k2 = scratch.keys2;
  std::vector<int32_t>& v2 = scratch.values2;
  k.resize(n), k2.resize(n), v2.resize(n);
  for (size_t i = 0; i < n; ++i) {
    uint64_t u;
    std::memcpy(&u, &keys[i], 8);
    k[i] = (u & 0x8000000000000000ull) ? ~u : (u | 0x8000000000000000ull);
  }
  constexpr int kBits = 11, kPasses = 6, kRadix = 1 << kBits;
  std::vector<uint32_t>& hist = scratch.hist;
  hist.assign(size_t(kPasses) * kRadix, 0);
  for (size_t i = 0; i < n; ++i)
    for (int p = 0; p < kPasses; ++p) ++hist[size_t(p) * kRadix + ((k[i] >> (p * kBits)) & (kRadix - 1))];
  for (int p = 0; p < kPasses; ++p) {
    uint32_t* h = &hist[size_t(p) * kRadix];
    if (n == 0 || h[(k[0] >> (p * kBits)) & (kRadix - 1)] == n) continue;  // digit constant
    uint32_t sum = 0;
    for (int d = 0; d < kRadix; ++d) {
      const uint32_t c = h[d];
      h[d] = sum;
      sum += c;
    }
    for (size_t i = 0; i < n; ++i) {
      const uint32_t pos = h[(k[i] >> (p * kBits)) & (kRadix - 1)]++;
      k2[pos] = k[i];
      v2[pos] = values[i];
    }
    k.swap(k2);
    values.swap(v2);
  }
  for (size_t i = 0; i < n; ++i) {
    uint64_t u = k[i];
    u = (u & 0x8000000000000000ull) ? (u & 0x7fffffffffffffffull) : ~u;
    std::memcpy(&keys[i], &u, 8);
  }
}

void radix_sort_by_key64(std::vector<double>& keys, std::vector<int32_t>& values) {
  Radix64Scratch scratch;
  radix_sort_by_key64(keys, values, scratch);
}

std::vector<int32_t> radix_argsort_descending(const std::vector<float>& keys) {
  std::vector<float> k(keys.size());
  std::vector<int32_t> v(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    k[i] = -keys[i];
    v[i] = static_cast<int32_t>(i);
  }
  std::vector<uint64_t> scratch;
  radix_sort_by_key(k, v, scratch);
  return v;
}

}  // namespace vob
