// Back to front by one key per primitive: the keys and radix sort phases that the cell and
// the triangle centroid orderers share.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "harness/bench/orderer.h"
#include "harness/bench/phase_clock.h"
#include "harness/geometry/vec3.h"
#include "harness/sort/radix_argsort.h"
#include "harness/sort/radix_sort.h"

namespace vob {

// Bounds of the keys of points in the box [lo, hi] seen from `eye` (padded against rounding;
// only a hint to the sort, which checks it): by_view, the depth dot(p - eye, f) over the
// corners; otherwise the distance from the eye to the box and to its farthest corner, no
// hint (lo > hi) when the eye is in or near the box (the range then spans many binades).
struct KeyRange {
  double lo = 1, hi = 0;
};
inline KeyRange key_range_from_box(Vec3 lo, Vec3 hi, Vec3 eye, Vec3 f, bool by_view) {
  double dmin = 1e300, dmax = -1e300, far = 0, near2 = 0;
  for (int m = 0; m < 8; ++m) {
    const Vec3 q{(m & 1) ? hi.x : lo.x, (m & 2) ? hi.y : lo.y, (m & 4) ? hi.z : lo.z};
    const double d = dot(q - eye, f);
    dmin = std::min(dmin, d), dmax = std::max(dmax, d), far = std::max(far, length(q - eye));
  }
  for (int a = 0; a < 3; ++a) {
    const double g = std::max({lo[a] - eye[a], 0.0, eye[a] - hi[a]});
    near2 += g * g;
  }
  const double pad = 1e-6 * (far + 1), near = std::sqrt(near2);
  if (by_view) return {dmin - pad, dmax + pad};
  if (near > 2 * pad) return {near - pad, far + pad};
  return {};
}

// The phases of a back-to-front order by key bits: "keys" runs `key_pass()`, which fills
// `sort` (RadixArgsort::make_keys or make_keys_by_runs), "radix sort" sorts them into ids.
template <class KeyPass>
Ordering order_from_key_pass(size_t n, KeyPass&& key_pass, RadixArgsort& sort, PhaseClock& clock) {
  {
    auto p = clock.phase("keys");
    key_pass();
  }
  Ordering out;
  {
    auto p = clock.phase("radix sort");
    out.order.resize(n);
    sort.sort_keys(out.order.data());
  }
  out.counters["radix passes"] = sort.passes();
  out.counters["top digit counted in key pass"] = sort.counted_in_key_pass() ? 1 : 0;
  out.counters["top digit scattered in key pass"] = sort.scattered_in_key_pass() ? 1 : 0;
  return out;
}

// The sort key of a distance: ascending float(-d) by its sortable bits puts the farthest first.
inline uint32_t descending_key_bits(double d) { return float_sort_key(static_cast<float>(-d)); }

// `key(i)` is primitive i's distance (larger = farther); the farthest comes first, ties in
// id order: ascending float(-key) by its sortable bits, stably. Each key is made, rounded
// and turned into its sortable bits in one streamed pass (in parallel when threads allow).
// [kmin, kmax] (optional, kmin > kmax: none) bounds key(i) a little loosely: the key pass
// then counts the sort's top digit too (RadixArgsort checks that every key fell inside).
template <class Key>
Ordering order_by_descending_key(size_t n, Key&& key, RadixArgsort& sort, PhaseClock& clock,
                                 double kmin = 1, double kmax = 0) {
  const bool guess = kmin <= kmax;  // -key ascending: kmax gives the least sortable bits
  const auto pass = [&] {
    sort.make_keys(n, [&](size_t i) { return descending_key_bits(key(i)); },
                   guess ? descending_key_bits(kmax) : 1u, guess ? descending_key_bits(kmin) : 0u);
  };
  return order_from_key_pass(n, pass, sort, clock);
}

}  // namespace vob
