// A triangle's three edge functions in three AVX2 lanes (lane 3 repeats edge 0), each lane
// the same operations as PolygonRaster::triangle_edges' Vec3 expressions (no FMA: the
// including file is built with -ffp-contract=off and target("avx2") has none), so the same
// bits. Include only from files that call these from functions built with target("avx2").
#pragma once
#include <immintrin.h>

#include "harness/geometry/vec3.h"
#include "harness/raster/sample_frame.h"

namespace vob::avx2 {

#define VOB_AVX2 __attribute__((target("avx2"), always_inline)) inline
VOB_AVX2 __m256d lt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
VOB_AVX2 __m256d eq(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
VOB_AVX2 __m256d gt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
VOB_AVX2 __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
VOB_AVX2 __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
VOB_AVX2 __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
VOB_AVX2 __m256d set(double a) { return _mm256_set1_pd(a); }
// a . (x, y, z) per lane, summed as dot(): (x + y) + z.
VOB_AVX2 __m256d dot3(__m256d mx, __m256d my, __m256d mz, const Vec3& v) {
  return add(add(mul(mx, set(v.x)), mul(my, set(v.y))), mul(mz, set(v.z)));
}

// Edge i runs from v[i] to v[i+1] taken in lexicographic order (pa, pb); m and c are
// triangle_edges' before its sign s = (lex order kept ? facing : -facing) is applied, and
// mx.. c here are already multiplied by s. facing: +-1 as triangle_edges computes it.
struct EdgeLanes {
  __m256d mx, my, mz, c;
};
VOB_AVX2 EdgeLanes edge_lanes(const SampleFrame& fr, const Vec3* v, double facing) {
  const __m256d vx = _mm256_set_pd(v[0].x, v[2].x, v[1].x, v[0].x), nx = _mm256_set_pd(v[1].x, v[0].x, v[2].x, v[1].x);
  const __m256d vy = _mm256_set_pd(v[0].y, v[2].y, v[1].y, v[0].y), ny = _mm256_set_pd(v[1].y, v[0].y, v[2].y, v[1].y);
  const __m256d vz = _mm256_set_pd(v[0].z, v[2].z, v[1].z, v[0].z), nz = _mm256_set_pd(v[1].z, v[0].z, v[2].z, v[1].z);
  // fwd = lex_less(v[i], v[i+1]): pa = v[i], pb = v[i+1]; else the other way round.
  const __m256d fwd =
      _mm256_or_pd(lt(vx, nx), _mm256_and_pd(eq(vx, nx), _mm256_or_pd(lt(vy, ny), _mm256_and_pd(eq(vy, ny), lt(vz, nz)))));
  const __m256d ax = _mm256_blendv_pd(nx, vx, fwd), ay = _mm256_blendv_pd(ny, vy, fwd), az = _mm256_blendv_pd(nz, vz, fwd);
  const __m256d bx = _mm256_blendv_pd(vx, nx, fwd), by = _mm256_blendv_pd(vy, ny, fwd), bz = _mm256_blendv_pd(vz, nz, fwd);
  const __m256d dx = sub(bx, ax), dy = sub(by, ay), dz = sub(bz, az);  // pb - pa
  __m256d mx, my, mz, c = _mm256_setzero_pd();
  if (fr.ortho()) {  // m = -cross(pb - pa, f), c = dot(cross(pb - pa, f), pa)
    const Vec3 f = fr.forward();
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
  const __m256d s = _mm256_blendv_pd(set(-facing), set(facing), fwd);
  return {mul(mx, s), mul(my, s), mul(mz, s), mul(c, s)};
}
// The top-left rule's ownership of an exactly zero value, as a lane mask (bit i: edge i).
VOB_AVX2 int owns_zero(const SampleFrame& fr, const EdgeLanes& e) {
  const __m256d a = dot3(e.mx, e.my, e.mz, fr.affine_dx()), b = dot3(e.mx, e.my, e.mz, fr.affine_dy());
  const __m256d cf = dot3(e.mx, e.my, e.mz, fr.forward());
  const __m256d zero = _mm256_setzero_pd();
  return _mm256_movemask_pd(_mm256_or_pd(
      gt(a, zero), _mm256_and_pd(eq(a, zero), _mm256_or_pd(lt(b, zero), _mm256_and_pd(eq(b, zero), gt(cf, zero))))));
}
#undef VOB_AVX2

}  // namespace vob::avx2
