// Back to front by one key per primitive: the keys and radix sort phases that the cell and
// the triangle centroid orderers share.
#pragma once
#include <cstddef>
#include <cstdint>

#include "harness/bench/orderer.h"
#include "harness/bench/phase_clock.h"
#include "harness/sort/radix_argsort.h"
#include "harness/sort/radix_sort.h"

namespace vob {

// `key(i)` is primitive i's distance (larger = farther); the farthest comes first, ties in
// id order: ascending float(-key) by its sortable bits, stably. Each key is made, rounded
// and turned into its sortable bits in one streamed pass (in parallel when threads allow).
template <class Key>
Ordering order_by_descending_key(size_t n, Key&& key, RadixArgsort& sort, PhaseClock& clock) {
  {
    auto p = clock.phase("keys");
    sort.make_keys(n, [&](size_t i) { return float_sort_key(static_cast<float>(-key(i))); });
  }
  Ordering out;
  {
    auto p = clock.phase("radix sort");
    out.order.resize(n);
    sort.sort_keys(out.order.data());
  }
  out.counters["radix passes"] = sort.passes();
  return out;
}

}  // namespace vob
