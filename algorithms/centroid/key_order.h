// Back to front by one key per primitive: the keys and radix sort phases that the cell and
// the triangle centroid orderers share.
#pragma once
#include <cstddef>
#include <cstdint>

#include "harness/bench/orderer.h"
#include "harness/bench/phase_clock.h"
#include "harness/sort/radix_sort.h"

namespace vob {

// `key(i)` is primitive i's distance (larger = farther); the farthest comes first.
template <class Key>
Ordering order_by_descending_key(size_t n, Key&& key, KeySort& sort, PhaseClock& clock) {
  {
    auto p = clock.phase("keys");
    sort.resize(n);
    for (size_t i = 0; i < n; ++i) {
      // Descending distance = ascending negated key.
      sort.keys[i] = static_cast<float>(-key(i));
      sort.ids[i] = static_cast<int32_t>(i);
    }
  }
  Ordering out;
  {
    auto p = clock.phase("radix sort");
    sort.sort();
    out.order = sort.ids;
  }
  return out;
}

}  // namespace vob
