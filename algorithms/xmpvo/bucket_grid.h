// XMPVO's uniform grid over the projected exterior faces: about one face per bucket,
// items listed per bucket in CSR form from their projected boxes.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace vob::xmpvo {

// An axis-aligned box in projected doubles.
struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

struct BucketGrid {
  int gw = 1, gh = 1;
  double gx0 = 0, gy0 = 0, cw = 1, ch = 1;

  // Covers `all` widened by `slack` with about `items` buckets, square where it can.
  void fit(const Box& all, double slack, size_t items);
  size_t buckets() const { return static_cast<size_t>(gw) * gh; }
  int col(double x) const { return static_cast<int>(std::clamp(std::floor((x - gx0) / cw), 0.0, gw - 1.0)); }
  int row(double y) const { return static_cast<int>(std::clamp(std::floor((y - gy0) / ch), 0.0, gh - 1.0)); }

  // CSR of items per bucket from their boxes.
  template <class BoxOf>
  void fill(const std::vector<int32_t>& items, BoxOf box_of, std::vector<int32_t>& off,
            std::vector<int32_t>& out) const {
    // Each item's bucket range once (four divisions), kept for the second pass; the grid's
    // width in a local, which the stores to `off` and `out` could otherwise alias.
    const int w = gw;
    off.assign(buckets() + 1, 0);
    spans_.resize(items.size());
    int32_t* count = off.data() + 1;
    for (size_t i = 0; i < items.size(); ++i) {
      const Box bx = box_of(items[i]);
      const std::array<int32_t, 4> s{col(bx.x0), col(bx.x1), row(bx.y0), row(bx.y1)};
      spans_[i] = s;
      for (int r = s[2]; r <= s[3]; ++r)
        for (int c = s[0]; c <= s[1]; ++c) ++count[static_cast<size_t>(r) * w + c];
    }
    for (size_t c = 1; c < off.size(); ++c) off[c] += off[c - 1];
    out.resize(off.back());
    int32_t* start = off.data();
    int32_t* dst = out.data();
    for (size_t i = 0; i < items.size(); ++i) {
      const std::array<int32_t, 4> s = spans_[i];
      const int32_t it = items[i];
      for (int r = s[2]; r <= s[3]; ++r)
        for (int c = s[0]; c <= s[1]; ++c) dst[start[static_cast<size_t>(r) * w + c]++] = it;
    }
    // The fill advanced each start to the next bucket's start: shift back.
    for (size_t c = off.size() - 1; c > 0; --c) off[c] = off[c - 1];
    off[0] = 0;
  }
  size_t bytes() const { return spans_.capacity() * sizeof(spans_[0]); }

 private:
  // fill()'s bucket range per item, kept from call to call (not the grid's state).
  mutable std::vector<std::array<int32_t, 4>> spans_;
};

}  // namespace vob::xmpvo
