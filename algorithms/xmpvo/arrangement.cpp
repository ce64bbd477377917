#include "algorithms/xmpvo/arrangement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <immintrin.h>

#include "algorithms/xmpvo/uv_filter.h"
#include "harness/cpu_features.h"

namespace vob::xmpvo {
namespace {
// Buckets per mean edge box area. On the 200k-cell helix that makes 6.7k buckets for 67k
// edges, the fastest pair loop of 0.03 to 1 bucket per edge tried (1: 1.7 times slower).
constexpr double kEdgeGridScale = 1.0;

// An edge as the pair loop holds it, copied per bucket.
struct BucketEdge {
  Box box;
  Uv ua, ub;
  int32_t a, b, id;
  bool unswept;  // Arrangement::unswept(id)
};

// A bucket's edges as the pair loop's first pass reads them, one array per field, eight
// entries of padding at the end (never read as edges: lanes past n are masked). The edges'
// points (ux, uy: the first; vx, vy: the second) only for the AVX-512 pass.
struct BucketLanes {
  std::vector<double> x0, y0, y1, ux, uy, vx, vy;
  std::vector<int32_t> a, b, unswept;  // unswept: -1 for an unswept edge, else 0
  void fill(const std::vector<BucketEdge>& local, bool points) {
    const size_t n = local.size(), m = n + 8;
    x0.resize(m), y0.resize(m), y1.resize(m), a.resize(m), b.resize(m), unswept.resize(m);
    for (size_t i = 0; i < n; ++i)
      x0[i] = local[i].box.x0, y0[i] = local[i].box.y0, y1[i] = local[i].box.y1, a[i] = local[i].a, b[i] = local[i].b,
      unswept[i] = -int32_t(local[i].unswept);
    if (!points) return;
    ux.resize(m), uy.resize(m), vx.resize(m), vy.resize(m);
    for (size_t i = 0; i < n; ++i)
      ux[i] = local[i].ua.first, uy[i] = local[i].ua.second, vx[i] = local[i].ub.first, vy[i] = local[i].ub.second;
  }
};

// build()'s first pass for edge ix, four later edges a step: the edges y = y0, y0 + 1, ...
// while their boxes start at or left of ix's right side (the run; y < n), kept in near
// (in order) when their boxes overlap in y, they share no point with ix, they are not both
// unswept, their corner is not clearly below the bucket's row (r > 0, below `floor`) and
// it lies in this bucket: clearly inside (beyond x_in and y_in), or `own_corner(y)` says
// so; returns how many. The same comparisons as the scalar loops, lane by lane
// (std::max(p, q) is max_pd(q, p)).
template <class OwnCorner>
__attribute__((target("avx2"))) size_t near_pairs_avx2(const BucketEdge& ix, const BucketLanes& l, size_t y0,
                                                       size_t n, bool below, double floor, double x_in, double y_in,
                                                       OwnCorner own_corner, uint32_t* near) {
  const __m256d ax1 = _mm256_set1_pd(ix.box.x1), ay0 = _mm256_set1_pd(ix.box.y0), ay1 = _mm256_set1_pd(ix.box.y1);
  const __m256d vfloor = _mm256_set1_pd(floor), vx_in = _mm256_set1_pd(x_in), vy_in = _mm256_set1_pd(y_in);
  const __m128i ia = _mm_set1_epi32(ix.a), ib = _mm_set1_epi32(ix.b);
  const __m128i ix_unswept = _mm_set1_epi32(-int32_t(ix.unswept));
  const int below_mask = below ? 0xF : 0;
  size_t m = 0;
  for (size_t y = y0; y < n; y += 4) {
    const __m256d x0 = _mm256_loadu_pd(&l.x0[y]), by0 = _mm256_loadu_pd(&l.y0[y]), by1 = _mm256_loadu_pd(&l.y1[y]);
    const int valid = n - y >= 4 ? 0xF : (1 << (n - y)) - 1;
    const int in_run = _mm256_movemask_pd(_mm256_cmp_pd(x0, ax1, _CMP_LE_OQ)) & valid;
    const int end = __builtin_ctz(~in_run);  // lanes [0, end) are in the run
    const int overlap = _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(ay0, by1, _CMP_LE_OQ),
                                                         _mm256_cmp_pd(by0, ay1, _CMP_LE_OQ)));
    const __m256d ly = _mm256_max_pd(by0, ay0);
    const int low = _mm256_movemask_pd(_mm256_cmp_pd(ly, vfloor, _CMP_LT_OQ)) & below_mask;
    const int inside = _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(x0, vx_in, _CMP_GT_OQ),
                                                        _mm256_cmp_pd(ly, vy_in, _CMP_GT_OQ)));
    const __m128i pa = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&l.a[y]));
    const __m128i pb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&l.b[y]));
    const __m128i shared = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(ia, pa), _mm_cmpeq_epi32(ia, pb)),
                                        _mm_or_si128(_mm_cmpeq_epi32(ib, pa), _mm_cmpeq_epi32(ib, pb)));
    const int apart = ~_mm_movemask_ps(_mm_castsi128_ps(shared)) & 0xF;
    const __m128i pu = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&l.unswept[y]));
    const int both_unswept = _mm_movemask_ps(_mm_castsi128_ps(_mm_and_si128(ix_unswept, pu)));
    int keep = overlap & apart & ~low & ~both_unswept & ((1 << end) - 1);
    // Corners near the bucket's sides (rare): the bucket's own column and row decide.
    for (int edge = keep & ~inside; edge != 0; edge &= edge - 1) {
      const int j = __builtin_ctz(edge);
      if (!own_corner(y + j)) keep &= ~(1 << j);
    }
    for (int j = 0; j < 4; ++j) {
      near[m] = static_cast<uint32_t>(y + j);
      m += (keep >> j) & 1;
    }
    if (end < 4) break;
  }
  return m;
}

// sign(x, p, q)'s o = (q - p).x * (x - p).y - (q - p).y * (x - p).x against +-1.001 quick,
// as 4-bit masks.
__attribute__((target("avx2"), always_inline)) inline void lane_signs(__m256d o, __m256d hi, __m256d lo, int& pos,
                                                                       int& neg) {
  pos = _mm256_movemask_pd(_mm256_cmp_pd(o, hi, _CMP_GT_OQ));
  neg = _mm256_movemask_pd(_mm256_cmp_pd(o, lo, _CMP_LT_OQ));
}

// The double filter of build() for the candidates cand[0, n) of edge ix, four a step: the
// four orient2d of each pair in lanes, the same operations as the scalar `sign`, so the
// same doubles. A pair whose four signs clear +-1.001 `quick` is decided here (apart: 0, else
// 1); any other is left to `scalar` (build()'s filtered_cross), which reaches the same
// answer for the quick signs and asks uv_sign for the rest. Writes {candidate, f} to
// maybe[q] for f != 0, in candidate order; returns q.
template <class Scalar>
__attribute__((target("avx2"))) size_t filter_pairs_avx2(const BucketEdge& ix, const BucketEdge* local,
                                                         const uint32_t* cand, size_t n, double quick,
                                                         std::pair<uint32_t, int>* maybe, Scalar&& scalar) {
  const __m256d hi = _mm256_set1_pd(1.001 * quick), lo = _mm256_set1_pd(-1.001 * quick);
  const __m256d ax = _mm256_set1_pd(ix.ua.first), ay = _mm256_set1_pd(ix.ua.second);
  const __m256d bx = _mm256_set1_pd(ix.ub.first), by = _mm256_set1_pd(ix.ub.second);
  const __m256d abx = _mm256_sub_pd(bx, ax), aby = _mm256_sub_pd(by, ay);
  size_t q = 0, k = 0;
  for (; k + 4 <= n; k += 4) {
    const BucketEdge &e0 = local[cand[k]], &e1 = local[cand[k + 1]], &e2 = local[cand[k + 2]],
                     &e3 = local[cand[k + 3]];
    const __m256d cx = _mm256_set_pd(e3.ua.first, e2.ua.first, e1.ua.first, e0.ua.first);
    const __m256d cy = _mm256_set_pd(e3.ua.second, e2.ua.second, e1.ua.second, e0.ua.second);
    const __m256d dx = _mm256_set_pd(e3.ub.first, e2.ub.first, e1.ub.first, e0.ub.first);
    const __m256d dy = _mm256_set_pd(e3.ub.second, e2.ub.second, e1.ub.second, e0.ub.second);
    const __m256d dcx = _mm256_sub_pd(dx, cx), dcy = _mm256_sub_pd(dy, cy);
    int pca, nca, pcb, ncb, pac, nac, pad, nad;
    // ca = sign(a, c, d), cb = sign(b, c, d), ac = sign(c, a, b), ad = sign(d, a, b).
    lane_signs(_mm256_sub_pd(_mm256_mul_pd(dcx, _mm256_sub_pd(ay, cy)), _mm256_mul_pd(dcy, _mm256_sub_pd(ax, cx))), hi, lo, pca, nca);
    lane_signs(_mm256_sub_pd(_mm256_mul_pd(dcx, _mm256_sub_pd(by, cy)), _mm256_mul_pd(dcy, _mm256_sub_pd(bx, cx))), hi, lo, pcb, ncb);
    lane_signs(_mm256_sub_pd(_mm256_mul_pd(abx, _mm256_sub_pd(cy, ay)), _mm256_mul_pd(aby, _mm256_sub_pd(cx, ax))), hi, lo, pac, nac);
    lane_signs(_mm256_sub_pd(_mm256_mul_pd(abx, _mm256_sub_pd(dy, ay)), _mm256_mul_pd(aby, _mm256_sub_pd(dx, ax))), hi, lo, pad, nad);
    const int certain = (pca | nca) & (pcb | ncb) & (pac | nac) & (pad | nad);
    const int apart = (pca & pcb) | (nca & ncb) | (pac & pad) | (nac & nad);
    for (int j = 0; j < 4; ++j) {
      const uint32_t y = cand[k + j];
      const int f = (certain >> j) & 1 ? !((apart >> j) & 1) : scalar(local[y]);
      maybe[q] = {y, f};
      q += f != 0;
    }
  }
  for (; k < n; ++k) {
    const int f = scalar(local[cand[k]]);
    maybe[q] = {cand[k], f};
    q += f != 0;
  }
  return q;
}
// Both passes at once for edge ix, eight later edges a step (AVX-512): the candidates of
// near_pairs_avx2, then the double filter of filter_pairs_avx2 on them, computed for every
// lane from the bucket's point arrays (no gather of scattered copies). Writes {candidate,
// f} to maybe[q] for f != 0 in candidate order, as filter_pairs_avx2 does, and up to seven
// entries past its last (room the caller gives); returns q. Adds the candidates to
// `candidates` and those left to `scalar` that it could not decide (f = 2) to `unsure`.
// The same comparisons and the same double operations, lane by lane (no FMA: this file is
// built with -ffp-contract=off).
template <class OwnCorner, class Scalar>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2"))) size_t near_filter_avx512(
    const BucketEdge& ix, const BucketEdge* local, const BucketLanes& l, size_t y0, size_t n, bool below, double floor,
    double x_in, double y_in, double quick, OwnCorner own_corner, Scalar&& scalar, std::pair<uint32_t, int>* maybe,
    int64_t& candidates, int64_t& unsure) {
  const __m512d ax1 = _mm512_set1_pd(ix.box.x1), ay0 = _mm512_set1_pd(ix.box.y0), ay1 = _mm512_set1_pd(ix.box.y1);
  const __m512d vfloor = _mm512_set1_pd(floor), vx_in = _mm512_set1_pd(x_in), vy_in = _mm512_set1_pd(y_in);
  const __m256i ia = _mm256_set1_epi32(ix.a), ib = _mm256_set1_epi32(ix.b);
  const __m256i ix_unswept = _mm256_set1_epi32(-int32_t(ix.unswept));
  const __mmask8 below_mask = below ? 0xFF : 0;
  const __m512d hi = _mm512_set1_pd(1.001 * quick), lo = _mm512_set1_pd(-1.001 * quick);
  const __m512d ax = _mm512_set1_pd(ix.ua.first), ay = _mm512_set1_pd(ix.ua.second);
  const __m512d bx = _mm512_set1_pd(ix.ub.first), by = _mm512_set1_pd(ix.ub.second);
  const __m512d abx = _mm512_sub_pd(bx, ax), aby = _mm512_sub_pd(by, ay);
  // Lane j's entry {y + j, 1}, as std::pair<uint32_t, int> lies in memory.
  const __m512i sure_entry = _mm512_add_epi64(_mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0), _mm512_set1_epi64(int64_t(1) << 32));
  size_t q = 0;
  for (size_t y = y0; y < n; y += 8) {
    const __mmask8 valid = n - y >= 8 ? __mmask8(0xFF) : __mmask8((1u << (n - y)) - 1);
    const __m512d x0 = _mm512_loadu_pd(&l.x0[y]), by0 = _mm512_loadu_pd(&l.y0[y]), by1 = _mm512_loadu_pd(&l.y1[y]);
    const unsigned in_run = _mm512_cmp_pd_mask(x0, ax1, _CMP_LE_OQ) & valid;
    const int end = __builtin_ctz(~in_run);  // lanes [0, end) are in the run
    const __mmask8 overlap = _mm512_cmp_pd_mask(ay0, by1, _CMP_LE_OQ) & _mm512_cmp_pd_mask(by0, ay1, _CMP_LE_OQ);
    const __m512d ly = _mm512_max_pd(by0, ay0);
    const __mmask8 low = _mm512_cmp_pd_mask(ly, vfloor, _CMP_LT_OQ) & below_mask;
    const __mmask8 inside = _mm512_cmp_pd_mask(x0, vx_in, _CMP_GT_OQ) & _mm512_cmp_pd_mask(ly, vy_in, _CMP_GT_OQ);
    const __m256i pa = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&l.a[y]));
    const __m256i pb = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&l.b[y]));
    const __mmask8 shared = _mm256_cmpeq_epi32_mask(ia, pa) | _mm256_cmpeq_epi32_mask(ia, pb) |
                            _mm256_cmpeq_epi32_mask(ib, pa) | _mm256_cmpeq_epi32_mask(ib, pb);
    const __m256i pu = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&l.unswept[y]));
    const __mmask8 both_unswept = _mm256_test_epi32_mask(ix_unswept, pu);
    unsigned keep = overlap & ~shared & ~low & ~both_unswept & ((1u << end) - 1);
    // Corners near the bucket's sides (rare): the bucket's own column and row decide.
    for (unsigned edge = keep & ~unsigned(inside); edge != 0; edge &= edge - 1) {
      const int j = __builtin_ctz(edge);
      if (!own_corner(y + j)) keep &= ~(1u << j);
    }
    candidates += __builtin_popcount(keep);
    // ca = sign(a, c, d), cb = sign(b, c, d), ac = sign(c, a, b), ad = sign(d, a, b).
    const __m512d cx = _mm512_loadu_pd(&l.ux[y]), cy = _mm512_loadu_pd(&l.uy[y]);
    const __m512d dx = _mm512_loadu_pd(&l.vx[y]), dy = _mm512_loadu_pd(&l.vy[y]);
    const __m512d dcx = _mm512_sub_pd(dx, cx), dcy = _mm512_sub_pd(dy, cy);
    const __m512d oca = _mm512_sub_pd(_mm512_mul_pd(dcx, _mm512_sub_pd(ay, cy)), _mm512_mul_pd(dcy, _mm512_sub_pd(ax, cx)));
    const __m512d ocb = _mm512_sub_pd(_mm512_mul_pd(dcx, _mm512_sub_pd(by, cy)), _mm512_mul_pd(dcy, _mm512_sub_pd(bx, cx)));
    const __m512d oac = _mm512_sub_pd(_mm512_mul_pd(abx, _mm512_sub_pd(cy, ay)), _mm512_mul_pd(aby, _mm512_sub_pd(cx, ax)));
    const __m512d oad = _mm512_sub_pd(_mm512_mul_pd(abx, _mm512_sub_pd(dy, ay)), _mm512_mul_pd(aby, _mm512_sub_pd(dx, ax)));
    const unsigned pca = _mm512_cmp_pd_mask(oca, hi, _CMP_GT_OQ), nca = _mm512_cmp_pd_mask(oca, lo, _CMP_LT_OQ);
    const unsigned pcb = _mm512_cmp_pd_mask(ocb, hi, _CMP_GT_OQ), ncb = _mm512_cmp_pd_mask(ocb, lo, _CMP_LT_OQ);
    const unsigned pac = _mm512_cmp_pd_mask(oac, hi, _CMP_GT_OQ), nac = _mm512_cmp_pd_mask(oac, lo, _CMP_LT_OQ);
    const unsigned pad = _mm512_cmp_pd_mask(oad, hi, _CMP_GT_OQ), nad = _mm512_cmp_pd_mask(oad, lo, _CMP_LT_OQ);
    const unsigned certain = (pca | nca) & (pcb | ncb) & (pac | nac) & (pad | nad);
    const unsigned apart = (pca & pcb) | (nca & ncb) | (pac & pad) | (nac & nad);
    if ((keep & ~certain) == 0) {  // nearly always: every kept pair decided here
      const __mmask8 sure = static_cast<__mmask8>(keep & ~apart);
      const __m512i entries = _mm512_add_epi64(sure_entry, _mm512_set1_epi64(int64_t(y)));
      _mm512_storeu_si512(maybe + q, _mm512_maskz_compress_epi64(sure, entries));
      q += static_cast<size_t>(__builtin_popcount(sure));
    } else {
      for (unsigned bits = keep; bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        const int f = (certain >> j) & 1 ? !((apart >> j) & 1) : scalar(local[y + j]);
        unsure += f == 2;
        maybe[q] = {static_cast<uint32_t>(y + j), f};
        q += f != 0;
      }
    }
    if (end < 8) break;
  }
  return q;
}

// Where the crossing of the edges e = (a, b) and f = (c, d) lies in projected doubles: the
// computed point with a generous error radius, inside both edges' boxes; their whole
// common box when the doubles are too close to call. From the bucket's copies (the
// projected points at hand).
ArrVertex crossing_vertex(const BucketEdge& e, const BucketEdge& f, double slack) {
  const Box &ba = e.box, &bb = f.box;
  const Box common{std::max(ba.x0, bb.x0), std::max(ba.y0, bb.y0), std::min(ba.x1, bb.x1),
                   std::min(ba.y1, bb.y1)};
  ArrVertex v{e.a, e.b, f.a, f.b, 0.5, common, e.id, f.id};
  const auto [ax, ay] = e.ua;
  const auto [bx, by] = e.ub;
  const auto [cx, cy] = f.ua;
  const auto [dx, dy] = f.ub;
  auto orient = [](double ox, double oy, double px, double py, double qx, double qy) {
    return (px - ox) * (qy - oy) - (py - oy) * (qx - ox);
  };
  const double oa = orient(cx, cy, dx, dy, ax, ay), ob = orient(cx, cy, dx, dy, bx, by);
  if (!(oa * ob < 0)) return v;
  const double t = oa / (oa - ob);
  const double mag = std::max({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by),
                               std::fabs(cx), std::fabs(cy), std::fabs(dx), std::fabs(dy)});
  // Edge lengths bounded from above by their L1 norms (cheaper than hypot).
  const double lcd = std::fabs(dx - cx) + std::fabs(dy - cy), lab = std::fabs(bx - ax) + std::fabs(by - ay);
  const double err = 1e-12 * mag * (lcd + 2 * lab + 2 * mag) / std::fabs(oa - ob) * lab + slack;
  const double x = ax + t * (bx - ax), y = ay + t * (by - ay);
  v.t = t;
  v.box = {std::max(common.x0, x - err), std::max(common.y0, y - err),
           std::min(common.x1, x + err), std::min(common.y1, y + err)};
  if (!(v.box.x0 <= v.box.x1 && v.box.y0 <= v.box.y1)) v.box = common;
  return v;
}

}  // namespace

// Out of the pair loop (rare: only pairs the exact test found not crossing come here), so
// that it does not weigh on the loop's registers and code.
void Arrangement::mark_on_line(const ViewGeometry& g, const std::vector<Vec3>& points, int32_t a, int32_t b,
                               int32_t c, int32_t d) {
  auto on = [&](int32_t x, int32_t p, int32_t q) {
    if (edge_side(g, points[p], points[q], points[x]) == 0) point_on_line[x] = 1;
  };
  on(a, c, d), on(b, c, d), on(c, a, b), on(d, a, b);
}

Box Arrangement::edge_box(const Projection& proj, int32_t e) const {
  const Box a = proj.point_box(edges[e].first), b = proj.point_box(edges[e].second);
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

int64_t Arrangement::build(const ExteriorFaces& ext, const Projection& proj, Signs& signs) {
  const std::vector<Vec3>& points = ext.points;
  vertices.clear();
  for (size_t p = 0; p < points.size(); ++p)
    if (proj.point_used[p]) vertices.push_back({static_cast<int32_t>(p), -1, -1, -1, 0, proj.point_box(p)});
  projected_vertices = vertices.size();
  build_edges(ext, proj);
  mark_edges(proj);
  box_.resize(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) box_[e] = edge_box(proj, static_cast<int32_t>(e));
  // The edges in a stable order of their boxes' left sides (NaN first, -0 as 0), by one
  // radix sort: the grid's fill keeps that order in every bucket, which the pair loop
  // needs. Sorting each bucket's copies instead (a count of smaller keys up to 64 edges,
  // std::sort beyond) cost 4.2 ms of the 200k helix's 55 ms phase.
  by_left_.resize(edges.size());
  left_key_.resize(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const double l = box_[e].x0;
    left_key_[e] = std::isnan(l) ? -INFINITY : l + 0.0;
    by_left_[e] = static_cast<int32_t>(e);
  }
  radix_sort_by_key64(left_key_, by_left_, left_sort_);
  const std::vector<int32_t>& ids = by_left_;
  // The edges' own grid, buckets about the size of a mean edge box: each edge then lies in
  // a few buckets, so a pair is met in few of them (the faces' grid, one face per bucket,
  // put each edge of a 200k-cell helix in 12 buckets of deep overlap; this one in 4).
  Box all{INFINITY, INFINITY, -INFINITY, -INFINITY};
  double mean_w = 0, mean_h = 0;
  for (const Box& b : box_) {
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
    mean_w += b.x1 - b.x0, mean_h += b.y1 - b.y0;
  }
  if (box_.empty()) all = {0, 0, 1, 1};
  const double n = std::max<double>(1.0, static_cast<double>(box_.size()));
  const double area = (all.x1 - all.x0) * (all.y1 - all.y0), cell = (mean_w / n) * (mean_h / n);
  const double target = cell > 0 ? std::clamp(kEdgeGridScale * area / cell, 1.0, n) : n;
  grid_.fit(all, 0, static_cast<size_t>(target));
  const BucketGrid& grid = grid_;
  grid.fill(ids, [&](int32_t e) { return box_[e]; }, edge_off, edge_items);
  int64_t candidates = 0;
  crossings_filtered = crossings_rechecked = 0;
  const bool filter = signs.mode == Mode::Exact && proj.uv_filter;
  // Every pair with a point on the other's line reaches the exact test: the filter cannot
  // certify a zero sign, and a point on the other edge leaves the pair not apart.
  lines_marked = filter;
  point_on_line.assign(points.size(), 0);
  const bool avx2 = lanes && cpu_has_avx2();
  // Both passes at once in AVX-512 lanes; with the double filter only (without it the two
  // passes stay).
  const bool avx512 = avx2 && lanes_avx512 && cpu_has_avx512() && filter;
  edge_vertex_off.assign(edges.size() + 1, 0);  // crossings per edge, at e + 1
  // Proper crossing from the double filter: 1 / 0 when certain, 2 when not. No early exit:
  // its outcomes are unpredictable, all four signs cost less than a mispredicted branch.
  const double slack = proj.slack;
  // `quick`: a bound on uv_sign's own error bound over a bucket (below), so that most signs
  // need orient2d's six operations alone; the rest get uv_sign, the same answers.
  double quick = 0;
  auto sign = [&](Uv x, Uv p, Uv q) {
    const double o = (q.first - p.first) * (x.second - p.second) - (q.second - p.second) * (x.first - p.first);
    const int s = (o > 1.001 * quick) - (o < -1.001 * quick);
    return s != 0 ? s : uv_sign(x, p, q, slack);
  };
  auto filtered_cross = [&](Uv a, Uv b, Uv c, Uv d) {
    const int ca = sign(a, c, d), cb = sign(b, c, d);
    const int ac = sign(c, a, b), ad = sign(d, a, b);
    // An edge's points certainly on one side of the other's line: no crossing.
    const bool apart = (ca * cb > 0) | (ac * ad > 0);
    const bool certain = (ca != 0) & (cb != 0) & (ac != 0) & (ad != 0);
    return apart ? 0 : certain ? 1 : 2;
  };
  // Each bucket's edges copied side by side first: the pair loop then reads no scattered
  // memory (not even the projected points). A pair is tested once, in the bucket of its
  // boxes' common lower corner. The copies are sorted by their boxes' left side, so the
  // pairs overlapping in x are a run after each edge (sweep and prune), and a pair's
  // corner lies left of this bucket's column whenever its later edge starts there.
  using Item = BucketEdge;
  std::vector<Item> local;
  std::vector<uint32_t> near;
  std::vector<std::pair<uint32_t, int>> maybe;
  BucketLanes bucket_lanes;
  const double tx = kSideBand * grid.cw, ty = kSideBand * grid.ch;
  // NaN first and never overlapping, as Box::overlaps has it.
  auto left = [](const Item& i) { return std::isnan(i.box.x0) ? -INFINITY : i.box.x0; };
  for (int r = 0; r < grid.gh; ++r)
    for (int c = 0; c < grid.gw; ++c) {
      const size_t cell = static_cast<size_t>(r) * grid.gw + c;
      const int32_t off = edge_off[cell], count = edge_off[cell + 1] - off;
      local.resize(count);
      for (int32_t i = 0; i < count; ++i) {
        const int32_t id = edge_items[off + i];
        const auto [a, b] = edges[id];
        local[i] = {box_[id], proj.uv[a], proj.uv[b], a, b, id, unswept_[id] != 0};
      }
      const double cx0 = grid.gx0 + c * grid.cw, cy0 = grid.gy0 + r * grid.ch;
      // uv_sign(x, p, q)'s bound for a pair of this bucket: with every box at most D wide
      // or high, |q - p| <= D and |x - p| <= 2 D per coordinate (x and p lie in boxes that
      // overlap), so it is at most 12 s D + 8 s^2 + 4e-15 D^2; 1% more for its rounding.
      double wide = 0;
      for (const Item& it : local) wide = std::max({wide, it.box.x1 - it.box.x0, it.box.y1 - it.box.y0});
      quick = 1.01 * (12 * slack * wide + 8 * slack * slack + 4e-15 * wide * wide);
      const size_t n = local.size();
      // The pairs whose later edge starts clearly left of the column have their corner in
      // a bucket to the left (tested there).
      size_t first = 0;
      if (c > 0)
        while (first < n && left(local[first]) < cx0 - tx) ++first;
      // Per edge x of the run, in three passes without a data-dependent branch each (about
      // 45% of a run passes the box tests and 37% of those cross, on a helix: branches on
      // them were mispredicted often): the later edges passing the box tests, kept in
      // `near`; of those, the ones the filter does not rule out, with its answer, in
      // `maybe`; then the crossings, in run order.
      near.resize(n + 4);  // the lanes' first pass writes up to three past its last
      maybe.resize(n + 8);  // the AVX-512 pass writes up to seven past its last
      if (avx2) bucket_lanes.fill(local, avx512);
      for (size_t x = 0; x < n; ++x) {
        const Item& ix = local[x];
        const Box& ba = ix.box;
        // The candidates: pairs whose corner lies in this bucket (near its sides, the
        // bucket's own column and row decide: rare).
        auto own_corner = [&](size_t y) {
          const double lx = local[y].box.x0, ly = std::max(ba.y0, local[y].box.y0);  // lx = max(ba.x0, bb.x0): sorted
          return grid.col(lx) == c && grid.row(ly) == r;
        };
        auto scalar = [&](const Item& iy) { return filtered_cross(ix.ua, ix.ub, iy.ua, iy.ub); };
        // The pairs the filter does not rule out, with its answers, in `maybe[0, q)`.
        size_t q = 0;
        if (avx512) {
          int64_t nc = 0, unsure = 0;
          q = near_filter_avx512(ix, local.data(), bucket_lanes, std::max(x + 1, first), n, r > 0, cy0 - ty, cx0 + tx,
                                 cy0 + ty, quick, own_corner, scalar, maybe.data(), nc, unsure);
          candidates += nc;
          crossings_filtered += nc - unsure;
          crossings_rechecked += unsure;
        } else {
          size_t nc = 0;
          if (avx2) {
            nc = near_pairs_avx2(ix, bucket_lanes, std::max(x + 1, first), n, r > 0, cy0 - ty, cx0 + tx, cy0 + ty,
                                 own_corner, near.data());
          } else {
            size_t m = 0;
            for (size_t y = std::max(x + 1, first); y < n && local[y].box.x0 <= ba.x1; ++y) {
              const Item& iy = local[y];
              const Box& bb = iy.box;
              // Overlap in y, no shared point (no proper crossing), and the corner not clearly
              // below this bucket's row.
              const double ly = std::max(ba.y0, bb.y0);
              const bool keep = (ba.y0 <= bb.y1) & (bb.y0 <= ba.y1) & (ix.a != iy.a) & (ix.a != iy.b) &
                                (ix.b != iy.a) & (ix.b != iy.b) & !((r > 0) & (ly < cy0 - ty));
              near[m] = static_cast<uint32_t>(y);
              m += keep;
            }
            for (size_t k = 0; k < m; ++k) {
              const Item& iy = local[near[k]];
              const double lx = iy.box.x0, ly = std::max(ba.y0, iy.box.y0);
              const bool inside = (lx > cx0 + tx) & (ly > cy0 + ty);
              near[nc] = near[k];
              nc += inside || own_corner(near[k]);
            }
            // Crossings of two inner edges of the unswept sheet: read by no sweep (the
            // lanes drop them themselves).
            if (ix.unswept) {
              size_t u = 0;
              for (size_t k = 0; k < nc; ++k) {
                near[u] = near[k];
                u += !local[near[k]].unswept;
              }
              nc = u;
            }
          }
          candidates += static_cast<int64_t>(nc);
          if (!filter) {
            for (size_t k = 0; k < nc; ++k) maybe[q++] = {near[k], 2};
          } else {
            if (avx2) {
              q = filter_pairs_avx2(ix, local.data(), near.data(), nc, quick, maybe.data(), scalar);
            } else {
              for (size_t k = 0; k < nc; ++k) {
                const int f = scalar(local[near[k]]);
                maybe[q] = {near[k], f};
                q += f != 0;
              }
            }
            int64_t unsure = 0;
            for (size_t k = 0; k < q; ++k) unsure += maybe[k].second == 2;
            crossings_filtered += static_cast<int64_t>(nc) - unsure;
            crossings_rechecked += unsure;
          }
        }
        for (size_t k = 0; k < q; ++k) {
          const Item& iy = local[maybe[k].first];
          const int32_t a = ix.a, b = ix.b, cc = iy.a, d = iy.b;
          if (maybe[k].second == 2 && !signs.crosses(points[a], points[b], points[cc], points[d])) {
            if (lines_marked) mark_on_line(signs.g, points, a, b, cc, d);
            continue;
          }
          vertices.push_back(crossing_vertex(ix, iy, slack));
          edge_vertex_off[ix.id + 1] += !ix.unswept;  // unswept edges get no lists
          edge_vertex_off[iy.id + 1] += !iy.unswept;
        }
      }
    }
  index_crossings(proj);
  return candidates;
}

// Unique edges (an edge shared by two exterior faces is one segment), with the faces of
// each, sorted by their points and then by face (as signed below).
void Arrangement::set_faces(const ExteriorFaces& ext) {
  // Key: the edge's points (smaller first); value: the face, times -1 - 1 when the face
  // has the edge the other way round.
  std::vector<std::pair<uint64_t, int32_t>> keys;
  keys.reserve(4 * ext.face.size());
  for (int32_t i = 0, nf = static_cast<int32_t>(ext.face.size()); i < nf; ++i) {
    const int n = ext.size[i];
    for (int k = 0; k < n; ++k) {
      uint32_t a = ext.vertex[4 * i + k], b = ext.vertex[4 * i + (k + 1) % n];
      const bool flip = a > b;
      if (flip) std::swap(a, b);
      keys.push_back({(uint64_t(a) << 32) | b, flip ? -1 - i : i});
    }
  }
  std::sort(keys.begin(), keys.end());
  all_edges_.clear();
  all_face_off_.assign(1, 0);
  all_faces_.resize(keys.size());
  all_face_dir_.resize(keys.size());
  for (size_t k = 0; k < keys.size(); ++k) {
    if (k == 0 || keys[k].first != keys[k - 1].first) {
      all_edges_.push_back({static_cast<int32_t>(keys[k].first >> 32),
                            static_cast<int32_t>(keys[k].first & 0xffffffffu)});
      all_face_off_.push_back(all_face_off_.back());
    }
    const int32_t f = keys[k].second;
    all_face_dir_[all_face_off_.back()] = f < 0 ? -1 : 1;
    all_faces_[all_face_off_.back()++] = f < 0 ? -1 - f : f;
  }
  faces_of_ = &ext;
  lists_are_all_ = false;
}

// The projected edges: set_faces' edges with their kept faces, those with none dropped
// (the same lists a sort of the kept faces' edge keys gives).
void Arrangement::build_edges(const ExteriorFaces& ext, const Projection& proj) {
  if (faces_of_ != &ext)
    throw std::logic_error("xmpvo::Arrangement: build() before set_faces() of these faces");
  if (proj.kept.size() == ext.face.size()) {  // every face kept: the lists as they are
    if (!lists_are_all_) {
      edges = all_edges_;
      edge_face_off = all_face_off_;
      edge_faces = all_faces_;
      edge_face_dir = all_face_dir_;
      lists_are_all_ = true;
    }
    return;
  }
  lists_are_all_ = false;
  const std::vector<int8_t>& facing = proj.facing;  // kept: facing != 0
  edges.clear();
  edge_face_off.assign(1, 0);
  edge_faces.clear();
  edge_face_dir.clear();
  for (size_t e = 0; e < all_edges_.size(); ++e) {
    for (int32_t x = all_face_off_[e]; x < all_face_off_[e + 1]; ++x) {
      if (facing[all_faces_[x]] == 0) continue;
      edge_faces.push_back(all_faces_[x]);
      edge_face_dir.push_back(all_face_dir_[x]);
    }
    if (static_cast<int32_t>(edge_faces.size()) == edge_face_off.back()) continue;  // none kept
    edges.push_back(all_edges_[e]);
    edge_face_off.push_back(static_cast<int32_t>(edge_faces.size()));
  }
}

size_t Arrangement::bytes() const {
  return edges.capacity() * 8 + (edge_off.capacity() + edge_items.capacity()) * 4 +
         (edge_face_off.capacity() + edge_faces.capacity() + edge_vertex_off.capacity()) * 4 +
         edge_face_dir.capacity() + edge_crossings.capacity() * sizeof(EdgeCrossing) +
         vertices.capacity() * sizeof(ArrVertex) + box_.capacity() * sizeof(Box) + swap_.capacity() * 8 + unswept_.capacity() +
         all_edges_.capacity() * 8 + (all_face_off_.capacity() + all_faces_.capacity()) * 4 +
         all_face_dir_.capacity() + point_on_line.capacity() +  // set_faces' lists, held for every view
         by_left_.capacity() * 4 + left_key_.capacity() * 8 + left_sort_.bytes() + grid_.bytes();
}

}  // namespace vob::xmpvo
