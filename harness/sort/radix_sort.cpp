#include "harness/sort/radix_sort.h"

#include <algorithm>

namespace vob {

void radix_sort_by_key(std::vector<float>& keys, std::vector<int32_t>& values,
                       std::vector<uint32_t>& scratch_keys, std::vector<int32_t>& scratch_values) {
  const size_t n = keys.size();
  // The transformed keys live in a per-thread buffer reused across calls: a fresh 4n-byte
  // allocation per call costs page faults comparable to one pass.
  thread_local std::vector<uint32_t> k;
  if (k.size() < n) k.resize(n);
  scratch_keys.resize(n);
  scratch_values.resize(n);
  // One pass transforms the keys and counts all four digit histograms.
  uint32_t hist[4][256] = {};
  for (size_t i = 0; i < n; ++i) {
    const uint32_t x = float_sort_key(keys[i]);
    k[i] = x;
    ++hist[0][x & 0xff];
    ++hist[1][(x >> 8) & 0xff];
    ++hist[2][(x >> 16) & 0xff];
    ++hist[3][x >> 24];
  }
  int passes[4], np = 0;
  for (int pass = 0; pass < 4; ++pass)
    if (n > 0 && hist[pass][(k[0] >> (8 * pass)) & 0xff] != n) passes[np++] = pass;  // else constant
  uint32_t* src_k = k.data();
  uint32_t* dst_k = scratch_keys.data();
  int32_t* src_v = values.data();
  int32_t* dst_v = scratch_values.data();
  bool in_values = true;
  for (int q = 0; q < np; ++q) {
    const int pass = passes[q];
    uint32_t* h = hist[pass];
    uint32_t sum = 0;
    for (int d = 0; d < 256; ++d) {
      const uint32_t c = h[d];
      h[d] = sum;
      sum += c;
    }
    const int shift = 8 * pass;
    if (q + 1 == np && !in_values) {
      // Last pass lands in the callers' vectors: values directly, keys as floats again.
      for (size_t i = 0; i < n; ++i) {
        const uint32_t x = src_k[i];
        const uint32_t pos = h[(x >> shift) & 0xff]++;
        const uint32_t u = (x & 0x80000000u) ? (x & 0x7fffffffu) : ~x;
        std::memcpy(&keys[pos], &u, 4);
        values[pos] = src_v[i];
      }
      return;
    }
    for (size_t i = 0; i < n; ++i) {
      const uint32_t pos = h[(src_k[i] >> shift) & 0xff]++;
      dst_k[pos] = src_k[i];
      dst_v[pos] = src_v[i];
    }
    std::swap(src_k, dst_k);
    std::swap(src_v, dst_v);
    in_values = !in_values;
  }
  if (!in_values) std::copy(src_v, src_v + n, values.data());
  // Keys back to floats in sorted order (inverse transform).
  for (size_t i = 0; i < n; ++i) {
    uint32_t u = src_k[i];
    u = (u & 0x80000000u) ? (u & 0x7fffffffu) : ~u;
    std::memcpy(&keys[i], &u, 4);
  }
}

void radix_sort_by_key64(std::vector<double>& keys, std::vector<int32_t>& values) {
  const size_t n = keys.size();
  std::vector<uint64_t> k(n), k2(n);
  std::vector<int32_t> v2(n);
  for (size_t i = 0; i < n; ++i) {
    uint64_t u;
    std::memcpy(&u, &keys[i], 8);
    k[i] = (u & 0x8000000000000000ull) ? ~u : (u | 0x8000000000000000ull);
  }
  constexpr int kBits = 11, kPasses = 6, kRadix = 1 << kBits;
  std::vector<uint32_t> hist(size_t(kPasses) * kRadix, 0);
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

std::vector<int32_t> radix_argsort_descending(const std::vector<float>& keys) {
  std::vector<float> k(keys.size());
  std::vector<int32_t> v(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    k[i] = -keys[i];
    v[i] = static_cast<int32_t>(i);
  }
  std::vector<uint32_t> sk;
  std::vector<int32_t> sv;
  radix_sort_by_key(k, v, sk, sv);
  return v;
}

}  // namespace vob
