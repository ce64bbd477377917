// LSD radix sort of (float key, int32 value) pairs: three 11-bit passes over words of the
// order-preserving transform of the float bits (sign bit flipped for positives, all bits for
// negatives) and the value, all three histograms counted in one pass, passes whose digit is
// constant skipped. Shared by HAVS's sort probe and KeySort below.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

namespace vob {

inline uint32_t float_sort_key(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}

// Sorts `values` by ascending `keys` (stable). Both vectors are permuted in place;
// `scratch` is a reused buffer (grown to 2 n words as needed).
void radix_sort_by_key(std::vector<float>& keys, std::vector<int32_t>& values, std::vector<uint64_t>& scratch);

// Ids sorted by float keys with the radix sort, buffers kept from frame to frame: what
// MPVONC's exterior cells and SXMPVO's exterior faces need per view (the centroid orderers
// use the fused RadixArgsort of radix_argsort.h).
class KeySort {
 public:
  std::vector<float> keys;   // fill with ids, then sort(): both come out ascending by key
  std::vector<int32_t> ids;
  void resize(size_t n) {
    keys.resize(n);
    ids.resize(n);
  }
  void clear() {
    keys.clear();
    ids.clear();
  }
  void push(float key, int32_t id) {
    keys.push_back(key);
    ids.push_back(id);
  }
  void sort() { radix_sort_by_key(keys, ids, scratch_); }
  size_t bytes() const { return (keys.capacity() + ids.capacity()) * 4 + scratch_.capacity() * 8; }

 private:
  std::vector<uint64_t> scratch_;
};

// radix_sort_by_key64's buffers, for callers that sort every frame: kept, they are neither
// allocated nor faulted in again.
struct Radix64Scratch {
  std::vector<uint64_t> keys, keys2;
  std::vector<int32_t> values2;
  std::vector<uint32_t> hist;
  size_t bytes() const {
    return (keys.capacity() + keys2.capacity()) * 8 + (values2.capacity() + hist.capacity()) * 4;
  }
};

// Double keys (order-preserving 64-bit transform, six 11-bit passes): for references that
// must not lose ties to float rounding. Sorts `values` by ascending `keys`, stable (-0.0
// sorts before +0.0).
void radix_sort_by_key64(std::vector<double>& keys, std::vector<int32_t>& values, Radix64Scratch& scratch);
void radix_sort_by_key64(std::vector<double>& keys, std::vector<int32_t>& values);

// Convenience: the permutation of [0, keys.size()) sorted by descending key.
std::vector<int32_t> radix_argsort_descending(const std::vector<float>& keys);

}  // namespace vob
