#version 450 core
// The k-buffer definitions shared by the draw and flush passes (kbuffer.h in GLSL).
// The program adds "#define K <k>" after the #version line.
struct Entry { float d; float v; int tag; };
// kbuffer.h nearer(): nearer, ties by tag (face * 2 + boundary).
bool nearer(Entry a, Entry b) { return a.d < b.d || (a.d == b.d && a.tag < b.tag); }
layout(binding = 0, rgba32ui) uniform coherent uimage2DArray entries;
layout(binding = 1, rgba32f) uniform coherent image2D accum;
layout(binding = 2, r32ui) uniform coherent uimage2D pstate;
// [0] eye, ortho; [1] forward, tau0; then the SampleFrame's row terms, then its column terms.
layout(std430, binding = 2) readonly buffer FrameBuf { dvec4 frame[]; };
Entry load_entry(ivec2 px, int i) {
  uvec4 u = imageLoad(entries, ivec3(px, i));
  return Entry(uintBitsToFloat(u.x), uintBitsToFloat(u.y), int(u.z));
}
void store_entry(ivec2 px, int i, Entry e) {
  imageStore(entries, ivec3(px, i), uvec4(floatBitsToUint(e.d), floatBitsToUint(e.v), uint(e.tag), 0u));
}
// 1 - exp(-x) for x >= 0 in double (GLSL has no double exp): exp(-x) = 2^-n exp(-r) with
// r = x - n ln 2 in [0, ln 2) and a Taylor sum for exp(-r) (error below 1e-16); a series for
// small x, where 1 - exp would cancel.
double one_minus_exp_neg(double x) {
  if (x < 0.01) return x * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x / 120.0))));
  if (x > 745.0) return 1.0;
  double n = floor(x * 1.4426950408889634);
  double r = x - n * 0.6931471805599453;
  double term = 1.0, sum = 1.0;
  for (int i = 1; i <= 18; ++i) {
    term *= -r / double(i);
    sum += term;
  }
  return 1.0 - ldexp(sum, -int(n));
}
// kbuffer.h Shading::segment: the boundary flip, then n1 -> n2 front to back when inside.
void segment(inout precise vec4 acc, inout bool inside, Entry n1, Entry n2) {
  if ((n1.tag & 1) != 0) inside = !inside;
  if (!inside) return;
  double tau0 = frame[1].w;
  double s = 0.5 * (double(n1.v) + double(n2.v));
  double x = tau0 * (0.25 + 0.75 * s) * (double(n2.d) - double(n1.d));
  double alpha = one_minus_exp_neg(x);
  precise float w = float((1.0 - double(acc.a)) * alpha);
  acc.r += w * float(0.15 + s * 0.85);
  acc.g += w * float(0.80 - s * 0.45);
  acc.b += w * float(0.30 + s * 0.40);
  acc.a += w;
}
