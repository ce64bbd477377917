// The k-buffer of one pixel (Callahan et al., section 3.2, and GPU-SORT of section 4).
//
// Followed from the paper:
// - A pixel keeps k entries (view distance d, scalar v, boundary tag). Faces arrive front to
//   back in centroid order; each incoming fragment f_new is compared with the k entries, the
//   nearest of the k+1 (n1) leaves the buffer, the nearest of the remaining k (n2) stays, and
//   the ray segment n1 -> n2 is composited front to back with colour and opacity from
//   (v1, v2, d2 - d1). f_new takes n1's slot (GPU-SORT: "write r1, r2, r3 back"). Entries are
//   kept unsorted, as in the hardware version (Fig. 3).
// - The buffer starts empty: the first k fragments are stored without compositing (the
//   paper's initialisation tag gives the same effect), and a final flush pops the remaining
//   entries nearest first, compositing each with the next.
// - Holes: fragments of boundary faces are tagged. The paper's second tag (all entries
//   internal/external, flipped "when the two closest entries are internal and the second
//   closest entry is on the boundary", and back "when two external fragments are chosen as
//   closest") is a per-pixel state that flips each time a boundary fragment leaves as n1.
//   We keep it as one `inside` bit per pixel (the paper stores it in the sign of every entry,
//   which is the same bit replicated): segments starting while outside (across a hole or
//   before the mesh) get zero colour and opacity. This is the complete two-tag logic the
//   paper describes but could not fit on its hardware.
// Interpreted:
// - Ties in d are broken by face id, so "nearest" is a strict total order and the exact
//   A-buffer order used as the reference is unique.
// - The preintegrated table is replaced by the exact integral of a segment with constant
//   extinction and colour taken at the mean of v1 and v2 (the harness' compositor ramp);
//   early ray termination is off (as in the paper's timings).
// Exactness (tested in tests/algorithms/havs): let m(f) be the number of fragments that
// arrived before f at the pixel and are farther than f. If m(f) <= k - 1 for every f, every
// n1 is the nearest fragment not yet composited and every n2 its true successor, so the
// composited segment sequence is the exact one. k_needed = 1 + max m(f) (0 if uncovered) is
// the per-pixel measure of Table 2 ("positions a fragment had to move").
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vob::havs {

struct KEntry {
  float d = 0;       // ray parameter t of the fragment
  float v = 0;       // scalar, normalised to [0, 1] by the mesh's scalar range
  int32_t tag = 0;   // face * 2 + (1 if the face is on the mesh boundary)
  bool boundary() const { return tag & 1; }
  int32_t face() const { return tag >> 1; }
};

// Strict total order: nearer, ties by face.
inline bool nearer(const KEntry& a, const KEntry& b) {
  return a.d < b.d || (a.d == b.d && a.tag < b.tag);
}

// Inserts f into the entries e[0..count) of capacity k. When full, calls
// segment(n1, n2) for the leaving nearest entry and its successor.
template <class Segment>
inline void kbuffer_insert(KEntry* e, uint8_t& count, int k, const KEntry& f, Segment&& segment) {
  if (count < k) {
    e[count++] = f;
    return;
  }
  int ni = -1;
  KEntry n1 = f;
  for (int i = 0; i < k; ++i)
    if (nearer(e[i], n1)) {
      n1 = e[i];
      ni = i;
    }
  if (ni >= 0) e[ni] = f;
  int j = 0;
  for (int i = 1; i < k; ++i)
    if (nearer(e[i], e[j])) j = i;
  segment(n1, e[j]);
}

// Pops the remaining entries nearest first, compositing each with the next.
template <class Segment>
inline void kbuffer_flush(KEntry* e, uint8_t& count, Segment&& segment) {
  while (count >= 2) {
    int i = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[i])) i = q;
    const KEntry n1 = e[i];
    e[i] = e[--count];
    int j = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[j])) j = q;
    segment(n1, e[j]);
  }
  count = 0;
}

// Front-to-back accumulation of one pixel with the boundary state.
struct PixelAccum {
  float r = 0, g = 0, b = 0, a = 0;
  bool inside = false;
};

// exp_neg's steps after the clamp, for a float or lane by lane for a vector of floats (the
// batch's opacities): the polynomial p for y0 = max(-x, -87), and n. (References only: a
// vector passed or returned by value changes the ABI where AVX is not enabled.)
template <class T>
__attribute__((always_inline)) inline void exp_neg_poly(const T& y0, T& n, T& p) {
  const float magic = 12582912.f;  // 1.5 * 2^23
  n = (y0 * 1.44269504088896341f + magic) - magic;
  T y = y0 - n * 0.693359375f;
  y = y - n * -2.12194440e-4f;
  const T z = y * y;
  p = T{} + 1.9875691500e-4f;  // 0 + c is c exactly
  p = p * y + 1.3981999507e-3f;
  p = p * y + 8.3334519073e-3f;
  p = p * y + 4.1665795894e-2f;
  p = p * y + 1.6666665459e-1f;
  p = p * y + 5.0000001201e-1f;
  p = p * z + y + 1.f;
}

// exp(-x) for x >= 0 in float, inline (the libm call and its dependency chain were the
// shading's cost): Cephes' expf, range reduction by n = round(-x log2 e) with ln 2 split in
// two, degree-5 polynomial, 2^n from the exponent bits. Relative error about 1 ulp (the
// bound below is checked in tests/algorithms/havs/havs_shading_test.cpp); x >= 87 gives
// exp(-87) ~ 1.6e-38, i.e. opacity 1. The magic constant rounds to nearest (the default
// mode; no -ffast-math here).
inline float exp_neg(float x) {
  float n, p;
  exp_neg_poly(std::max(-x, -87.f), n, p);
  const int32_t bits = (int32_t(n) + 127) << 23;
  float scale;
  __builtin_memcpy(&scale, &bits, 4);
  return p * scale;
}

// alpha[i] = Shading::opacity(tau, s[i], dd[i]) for i < n, four at a time with SSE2, or
// eight with AVX2 (opacities_avx2, where the CPU has it): the same float operations lane by
// lane, so the same bits (GCC does not vectorise the scalar loop itself under its default
// -ftrapping-math).
inline void opacities(float tau, const float* s, const float* dd, float* alpha, int n);
inline void opacities_avx2(float tau, const float* s, const float* dd, float* alpha, int n);

// The harness compositor's transfer function (render/compositor.cpp): green-to-pink ramp,
// extinction tau0 * (0.25 + 0.75 s).
// The k-buffer composites in float with one inline exp per segment (exp_neg; precise =
// false); the analysis' exact image is the reference, in double with std::exp (precise =
// true). The two opacities differ by float rounding: |alpha_float - alpha_double| <= 4e-7
// for every segment (tests/algorithms/havs/havs_shading_test.cpp sweeps the extinction
// range), so a pixel's colour moves by at most that times its number of segments.
struct Shading {
  double tau0 = 1;
  bool precise = false;
  // Applies the boundary logic; composites n1 -> n2 when inside. Returns whether it did.
  bool segment(PixelAccum& px, const KEntry& n1, const KEntry& n2) const {
    if (n1.boundary()) px.inside = !px.inside;
    if (!px.inside) return false;
    if (precise)
      composite_double(px, n1, n2);
    else
      composite(px, n1.v, n2.v, n2.d - n1.d);
    return true;
  }
  // The float path: segment of scalars v1, v2 and length dd, in three steps that a caller
  // may also run over a batch of segments (the k = 2 pass: opacities vectorised).
  void composite(PixelAccum& px, float v1, float v2, float dd) const {
    const float s = mean(v1, v2);
    accumulate(px, s, opacity(float(tau0), s, dd));
  }
  static float mean(float v1, float v2) { return 0.5f * (v1 + v2); }
  static float opacity(float tau, float s, float dd) { return 1.f - exp_neg(tau * (0.25f + 0.75f * s) * dd); }
  static void accumulate(PixelAccum& px, float s, float alpha) {
    const float w = (1.f - px.a) * alpha;
    px.r += w * (0.15f + s * 0.85f);
    px.g += w * (0.80f - s * 0.45f);
    px.b += w * (0.30f + s * 0.40f);
    px.a += w;
  }
  __attribute__((noinline)) void composite_double(PixelAccum& px, const KEntry& n1, const KEntry& n2) const {
    const double s = 0.5 * (double(n1.v) + double(n2.v));
    const double alpha = 1.0 - std::exp(-tau0 * (0.25 + 0.75 * s) * (double(n2.d) - n1.d));
    const float w = float((1.0 - px.a) * alpha);
    px.r += w * float(0.15 + s * 0.85);
    px.g += w * float(0.80 - s * 0.45);
    px.b += w * float(0.30 + s * 0.40);
    px.a += w;
  }
};

namespace detail {
// alpha[0, lanes) from s and dd, in lanes of GCC's vector types: V holds floats, VI as many
// int32. Each operator is one lane-wise float operation of Shading::opacity and exp_neg, in
// their order; max(y, -87) is (y > -87 ? y : -87), as maxps takes it.
template <class V, class VI>
__attribute__((always_inline)) inline void opacity_lanes(float tau, const float* sp, const float* ddp, float* alpha) {
  V s, dd;
  __builtin_memcpy(&s, sp, sizeof s);
  __builtin_memcpy(&dd, ddp, sizeof dd);
  const V x = tau * (0.25f + 0.75f * s) * dd;
  const V y = -x, y0 = y > -87.f ? y : V{} - 87.f;
  V nf, p;
  exp_neg_poly(y0, nf, p);
  const VI bits = (__builtin_convertvector(nf, VI) + 127) << 23;
  const V a = 1.f - p * __builtin_bit_cast(V, bits);
  __builtin_memcpy(alpha, &a, sizeof a);
}
typedef float V4 __attribute__((vector_size(16)));
typedef int32_t V4i __attribute__((vector_size(16)));
typedef float V8 __attribute__((vector_size(32)));
typedef int32_t V8i __attribute__((vector_size(32)));
}  // namespace detail

inline void opacities(float tau, const float* s, const float* dd, float* alpha, int n) {
  int i = 0;
  for (; i + 4 <= n; i += 4) detail::opacity_lanes<detail::V4, detail::V4i>(tau, s + i, dd + i, alpha + i);
  for (; i < n; ++i) alpha[i] = Shading::opacity(tau, s[i], dd[i]);
}

__attribute__((target("avx2"))) inline void opacities_avx2(float tau, const float* s, const float* dd, float* alpha,
                                                          int n) {
  int i = 0;
  for (; i + 8 <= n; i += 8) detail::opacity_lanes<detail::V8, detail::V8i>(tau, s + i, dd + i, alpha + i);
  opacities(tau, s + i, dd + i, alpha + i, n - i);
}

}  // namespace vob::havs
