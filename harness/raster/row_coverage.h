// The exact rule's innermost loop: which samples of one row a triangle covers, and the ray
// parameter t at each. PolygonRaster::scan and SXMPVO's tiny-face path both spend most of
// their time here (one test of three edge functions and one depth per sample).
//
// The AVX2 kernel takes four samples a step (AVX-512: two runs of up to four, eight lanes)
// with the very operations of the scalar loop,
// each lane rounded as the scalar double would be (no multiply-adds: the file is built with
// -ffp-contract=off and the kernel's target has no FMA), so both give the same samples and
// the same t bits (tests/harness/raster/row_coverage_test.cpp), and a shared edge stays
// watertight between a face scanned by either.
#pragma once
#include <cstdint>
#include <type_traits>

#include "harness/raster/sample_frame.h"

namespace vob {

// Edge i of a triangle: inside when c[i] + m[i] . X(sx, sy) > 0, or == 0 and own[i].
// A NaN value rejects nothing (as PolygonRaster::inside).
struct RowEdges {
  double mx[4], my[4], mz[4], c[4];  // [3]: unused (room for a four-lane store)
  bool own[3];
};

// The depth plane: t = -(n . X + d) * inv_nf (orthographic) or num / (n . X) * |X|; a
// sample counts when t > 0 (orthographic: t >= 0) and t is finite.
struct RowDepth {
  Vec3 n;
  double d = 0, num = 0, inv_nf = 0;
};

// A run of samples of row sy, columns [x0, x1] with x1 - x0 < kRowChunk.
struct RowSpan {
  int sy, x0, x1;
};
constexpr int kRowChunk = 64;

// Where the kernel writes its hits: hit j is sample (sx[j], sy[j]) at t[j]. Room for
// kRowHitCap hits plus the kernels' slack (they store four or eight lanes at a time).
constexpr int kRowHitCap = 256;
struct RowHits {
  int sx[kRowHitCap + 8], sy[kRowHitCap + 8];
  double t[kRowHitCap + 8];
};

// Writes the covered samples of the spans (their lengths summing to at most kRowHitCap) to
// hits, span by span, left to right, and returns their number.
using RowCoverageFn = int (*)(const SampleFrame& frame, const RowEdges& e, const RowDepth& depth,
                              const RowSpan* spans, int count, RowHits& hits);

RowCoverageFn row_coverage();           // the widest kernel this CPU runs: AVX-512, AVX2, else the scalar loop
RowCoverageFn row_coverage_baseline();  // the scalar loop (tests compare the kernels to it)
RowCoverageFn row_coverage_avx2();      // the AVX2 kernel alone; nullptr without AVX2
RowCoverageFn row_coverage_avx512();    // the AVX-512 kernel alone; nullptr without AVX-512 F/VL/DQ

// Collects spans and calls emit(sx, sy, t) for every covered sample, a batch of spans at a
// time (one kernel call, one setup, per batch rather than per row); an emit taking
// (const RowHits&, n) gets each batch's hits [0, n) at once.
class RowScanner {
 public:
  RowScanner(RowCoverageFn fn, const SampleFrame& frame, const RowEdges& e, const RowDepth& depth)
      : fn_(fn), frame_(frame), e_(e), depth_(depth) {}
  template <class Emit>
  void add(int sy, int x0, int x1, Emit&& emit) {
    for (int a = x0; a <= x1; a += kRowChunk) {
      const int b = x1 - a < kRowChunk ? x1 : a + kRowChunk - 1;
      if (samples_ + (b - a + 1) > kRowHitCap || count_ == kSpans) flush(emit);
      spans_[count_++] = {sy, a, b};
      samples_ += b - a + 1;
    }
  }
  template <class Emit>
  void flush(Emit&& emit) {
    if (count_ == 0) return;
    const int n = fn_(frame_, e_, depth_, spans_, count_, hits_);
    if constexpr (std::is_invocable_v<Emit&, const RowHits&, int>) {
      if (n > 0) emit(static_cast<const RowHits&>(hits_), n);
    } else {
      for (int j = 0; j < n; ++j) emit(hits_.sx[j], hits_.sy[j], hits_.t[j]);
    }
    count_ = samples_ = 0;
  }

 private:
  static constexpr int kSpans = 64;
  RowCoverageFn fn_;
  const SampleFrame& frame_;
  const RowEdges& e_;
  const RowDepth& depth_;
  RowSpan spans_[kSpans];
  int count_ = 0, samples_ = 0;
  RowHits hits_;
};

}  // namespace vob
