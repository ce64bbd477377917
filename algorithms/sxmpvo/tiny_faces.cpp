#include "algorithms/sxmpvo/tiny_faces.h"

#include <algorithm>

#include "harness/raster/row_step_avx2.h"
#include "harness/raster/sample_centres.h"

namespace vob::sxmpvo {

// Built for AVX2 too, chosen at load time: there ceil and floor are one instruction each
// (the baseline's are a dozen); both are exact, so both builds give the same boxes.
__attribute__((target_clones("avx2", "default"))) BoxKind sample_box(const SampleFrame& frame,
                                                                     const ProjectedVertex* q, int n,
                                                                     SampleRect& box) {
  double lx = 0, hx = 0, ly = 0, hy = 0;
  for (int i = 0; i < n; ++i) {
    if (!q[i].in_front) return BoxKind::Large;
    const double x = q[i].x, y = q[i].y;
    if (i == 0 || x < lx) lx = x;
    if (i == 0 || x > hx) hx = x;
    if (i == 0 || y < ly) ly = y;
    if (i == 0 || y > hy) hy = y;
  }
  // The samples PolygonRaster::may_cover_a_sample would let through (the same function).
  if (!sample_centres_in(frame, lx, hx, ly, hy, box)) return BoxKind::None;
  const int64_t samples = int64_t(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
  return samples <= kTinyMaxSamples ? BoxKind::Tiny : BoxKind::Large;
}

namespace {

int entries_scalar(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t item,
                   int32_t rank, ABuffer::Raw* dst) {
  const int64_t cols = fr.cols();
  int n = 0;
  scan_tiny_triangle(fr, v, phase1_sign, box, [&](int sx, int sy, double t) {
    dst[n++] = ABuffer::Raw(t, item, static_cast<int32_t>(sy * cols + sx), rank);
  });
  return n;
}

// The row kernel's steps (row_step_avx2.h) over the box, each step's four entries written
// whatever its mask (the count steps by the covered ones): no jump per sample or per hit.
template <bool kOrtho>
__attribute__((target("avx2,popcnt"))) int entries_avx2(const SampleFrame& fr, const RowEdges& e, const RowDepth& p,
                                                 const SampleRect& box, int32_t item, int32_t rank,
                                                 ABuffer::Raw* dst) {
  const double *cx = fr.col_x(), *cy = fr.col_y(), *cz = fr.col_z();
  const RowStepAvx2 k(e, p);
  const int cols = fr.cols();
  int n = 0;
  for (int sy = box.y0; sy <= box.y1; ++sy) {
    const Vec3 row = fr.row_term(sy);
    const __m256d rx = _mm256_set1_pd(row.x), ry = _mm256_set1_pd(row.y), rz = _mm256_set1_pd(row.z);
    for (int sx = box.x0; sx <= box.x1; sx += 4) {
      __m256d t;
      const int mask = k.step<kOrtho>(rx, ry, rz, cx, cy, cz, sx, box.x1, t);
      alignas(32) double ts[4];
      alignas(16) int32_t px[4];
      _mm256_store_pd(ts, RowStepAvx2::compact_t(t, mask));
      _mm_store_si128(reinterpret_cast<__m128i*>(px),
                      _mm_add_epi32(_mm_set1_epi32(sy * cols + sx), RowStepAvx2::compact_lanes(mask)));
      for (int j = 0; j < 4; ++j) dst[n + j] = ABuffer::Raw(ts[j], item, px[j], rank);
      n += __builtin_popcount(mask);
    }
  }
  return n;
}

// Lane-wise helpers for the setup below (lambdas would not inherit its target).
#define VOB_AVX2 __attribute__((target("avx2"), always_inline)) inline
VOB_AVX2 __m256d lt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
VOB_AVX2 __m256d eq(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
VOB_AVX2 __m256d gt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
VOB_AVX2 __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
VOB_AVX2 __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
VOB_AVX2 __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
VOB_AVX2 __m256d set(double a) { return _mm256_set1_pd(a); }
#undef VOB_AVX2
}  // namespace

// tiny_triangle_rows with the three edges in three lanes (lane 3 repeats edge 0): the same
// operations per lane as the scalar Vec3 expressions, so the same bits; the ownership
// tests as lane masks instead of a chain of scalar compares.
__attribute__((target("avx2"))) bool tiny_triangle_rows_avx2(const SampleFrame& fr, const Vec3* v,
                                                             int phase1_sign, RowEdges& e, RowDepth& depth) {
  if (!detail::depth_plane(fr, v, depth)) return false;
  const bool ortho = fr.ortho();
  const __m256d vx = _mm256_set_pd(v[0].x, v[2].x, v[1].x, v[0].x), nx = _mm256_set_pd(v[1].x, v[0].x, v[2].x, v[1].x);
  const __m256d vy = _mm256_set_pd(v[0].y, v[2].y, v[1].y, v[0].y), ny = _mm256_set_pd(v[1].y, v[0].y, v[2].y, v[1].y);
  const __m256d vz = _mm256_set_pd(v[0].z, v[2].z, v[1].z, v[0].z), nz = _mm256_set_pd(v[1].z, v[0].z, v[2].z, v[1].z);
  // fwd (lex_less_flat(v[i], v[i+1])): pa = v[i], pb = v[i+1]; else the other way round.
  const __m256d fwd =
      _mm256_or_pd(lt(vx, nx), _mm256_and_pd(eq(vx, nx), _mm256_or_pd(lt(vy, ny), _mm256_and_pd(eq(vy, ny), lt(vz, nz)))));
  const __m256d ax = _mm256_blendv_pd(nx, vx, fwd), ay = _mm256_blendv_pd(ny, vy, fwd), az = _mm256_blendv_pd(nz, vz, fwd);
  const __m256d bx = _mm256_blendv_pd(vx, nx, fwd), by = _mm256_blendv_pd(vy, ny, fwd), bz = _mm256_blendv_pd(vz, nz, fwd);
  const __m256d dx = sub(bx, ax), dy = sub(by, ay), dz = sub(bz, az);  // pb - pa
  __m256d mx, my, mz, c = _mm256_setzero_pd();
  const Vec3 f = fr.forward();
  if (ortho) {  // m = -cross(pb - pa, f), c = dot(cross(pb - pa, f), pa)
    const __m256d fx = set(f.x), fy = set(f.y), fz = set(f.z);
    const __m256d px = sub(mul(dy, fz), mul(dz, fy)), py = sub(mul(dz, fx), mul(dx, fz)), pz = sub(mul(dx, fy), mul(dy, fx));
    c = add(add(mul(px, ax), mul(py, ay)), mul(pz, az));
    const __m256d neg = set(-0.0);
    mx = _mm256_xor_pd(px, neg), my = _mm256_xor_pd(py, neg), mz = _mm256_xor_pd(pz, neg);
  } else {  // m = cross(pa - eye, pb - pa)
    const Vec3 eye = fr.eye();
    const __m256d qx = sub(ax, set(eye.x)), qy = sub(ay, set(eye.y)), qz = sub(az, set(eye.z));
    mx = sub(mul(qy, dz), mul(qz, dy)), my = sub(mul(qz, dx), mul(qx, dz)), mz = sub(mul(qx, dy), mul(qy, dx));
  }
  const double facing = -phase1_sign;  // as tiny_triangle_rows
  const __m256d s = _mm256_blendv_pd(set(-facing), set(facing), fwd);
  mx = mul(mx, s), my = mul(my, s), mz = mul(mz, s), c = mul(c, s);
  const Vec3 ex = fr.affine_dx(), ey = fr.affine_dy();
  const __m256d a = add(add(mul(mx, set(ex.x)), mul(my, set(ex.y))), mul(mz, set(ex.z)));
  const __m256d b = add(add(mul(mx, set(ey.x)), mul(my, set(ey.y))), mul(mz, set(ey.z)));
  const __m256d cf = add(add(mul(mx, set(f.x)), mul(my, set(f.y))), mul(mz, set(f.z)));
  const __m256d zero = _mm256_setzero_pd();
  const __m256d own = _mm256_or_pd(
      gt(a, zero), _mm256_and_pd(eq(a, zero), _mm256_or_pd(lt(b, zero), _mm256_and_pd(eq(b, zero), gt(cf, zero)))));
  _mm256_storeu_pd(e.mx, mx), _mm256_storeu_pd(e.my, my), _mm256_storeu_pd(e.mz, mz), _mm256_storeu_pd(e.c, c);
  const int m = _mm256_movemask_pd(own);
  e.own[0] = m & 1, e.own[1] = (m >> 1) & 1, e.own[2] = (m >> 2) & 1;
  return true;
}

namespace {

int entries_avx2_any(const SampleFrame& fr, const Vec3* v, int phase1_sign, const SampleRect& box, int32_t item,
                     int32_t rank, ABuffer::Raw* dst) {
  RowEdges e;
  RowDepth depth;
  if (!tiny_triangle_rows_avx2(fr, v, phase1_sign, e, depth)) return 0;
  return fr.ortho() ? entries_avx2<true>(fr, e, depth, box, item, rank, dst)
                    : entries_avx2<false>(fr, e, depth, box, item, rank, dst);
}

}  // namespace

TinyEntriesFn tiny_entries() { return row_coverage_uses_avx2() ? &entries_avx2_any : &entries_scalar; }
TinyEntriesFn tiny_entries_baseline() { return &entries_scalar; }

}  // namespace vob::sxmpvo
