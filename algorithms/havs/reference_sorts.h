// The comparison sorts of HAVS Table 1 on (float key, int32 id) pairs, ascending by key:
// shellsort (Ciura's gaps extended by x2.25, as in Sedgewick's text), heapsort
// (std::make_heap + std::sort_heap), quicksort (std::sort, introsort), and std::stable_sort.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace vob::havs {

using KeyId = std::pair<float, int32_t>;
inline bool key_less(const KeyId& a, const KeyId& b) { return a.first < b.first; }

inline void shellsort(std::vector<KeyId>& a) {
  std::vector<size_t> gaps = {1, 4, 10, 23, 57, 132, 301, 701};
  while (gaps.back() * 9 / 4 < a.size()) gaps.push_back(gaps.back() * 9 / 4);
  for (auto g = gaps.rbegin(); g != gaps.rend(); ++g) {
    const size_t h = *g;
    for (size_t i = h; i < a.size(); ++i) {
      const KeyId v = a[i];
      size_t j = i;
      for (; j >= h && v.first < a[j - h].first; j -= h) a[j] = a[j - h];
      a[j] = v;
    }
  }
}

inline void heapsort(std::vector<KeyId>& a) {
  std::make_heap(a.begin(), a.end(), key_less);
  std::sort_heap(a.begin(), a.end(), key_less);
}

inline void quicksort(std::vector<KeyId>& a) { std::sort(a.begin(), a.end(), key_less); }
inline void stable_sort(std::vector<KeyId>& a) { std::stable_sort(a.begin(), a.end(), key_less); }

}  // namespace vob::havs
