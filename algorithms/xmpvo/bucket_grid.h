// XMPVO's uniform grid over the projected exterior faces: about one face per bucket,
// items listed per bucket in CSR form from their projected boxes.
#pragma once
#include <algorithm>
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
    off.assign(buckets() + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      for (int32_t it : items) {
        const Box bx = box_of(it);
        const int c0 = col(bx.x0), c1 = col(bx.x1), r0 = row(bx.y0), r1 = row(bx.y1);
        for (int r = r0; r <= r1; ++r)
          for (int c = c0; c <= c1; ++c) {
            const size_t cell = static_cast<size_t>(r) * gw + c;
            if (pass == 0) ++off[cell + 1];
            else out[off[cell]++] = it;
          }
      }
      if (pass == 0) {
        for (size_t c = 1; c < off.size(); ++c) off[c] += off[c - 1];
        out.resize(off.back());
      } else {
        // The fill advanced each start to the next bucket's start: shift back.
        for (size_t c = off.size() - 1; c > 0; --c) off[c] = off[c - 1];
        off[0] = 0;
      }
    }
  }
};

}  // namespace vob::xmpvo
