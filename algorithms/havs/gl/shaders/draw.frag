// Draw pass: the read-modify-write of kbuffer_insert for each fragment (after common.glsl).
flat in int vtag;
uniform int nrows;
struct Face { dvec4 plane; dvec4 onp; dvec4 s1; };  // n, d; a point on the plane, quad slot; g, c
layout(std430, binding = 0) readonly buffer FaceBuf { Face faces[]; };
layout(std430, binding = 1) readonly buffer QuadBuf { dvec4 quads[]; };  // per quad: half 0-2-3, split
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  // PolygonRaster::depth at the sample's X = row(sy) + col(sx), and FaceData::scalar_at.
  dvec3 X = frame[2 + px.y].xyz + frame[2 + nrows + px.x].xyz;
  Face F = faces[vtag >> 1];
  dvec3 n = F.plane.xyz;
  bool ortho = frame[0].w != 0.0;
  dvec3 eye = frame[0].xyz;
  double t;
  dvec3 p;
  if (ortho) {
    t = -(dot(n, X) + F.plane.w) * (1.0 / dot(n, frame[1].xyz));
    p = X + frame[1].xyz * t;
  } else {
    double num = -dot(n, eye - F.onp.xyz);
    double len = sqrt(dot(X, X));
    t = num / dot(n, X) * len;
    p = eye + X * (t / len);
  }
  if (!(ortho ? t >= 0.0 : t > 0.0) || isinf(t) || isnan(t)) discard;
  int q = int(F.onp.w);
  double s = (q >= 0 && dot(quads[2 * q + 1].xyz, p) + quads[2 * q + 1].w > 0.0)
                 ? dot(quads[2 * q].xyz, p) + quads[2 * q].w
                 : dot(F.s1.xyz, p) + F.s1.w;
  Entry f = Entry(float(t), float(clamp(s, 0.0, 1.0)), vtag);

  // kbuffer_insert: read, modify, write. Without interlock nothing orders this sequence
  // against another fragment of the same pixel in the same draw (Fig. 5).
  uint st = imageLoad(pstate, px).x;
  uint count = st & 0xffu;
  bool inside = (st & 0x100u) != 0u;
  uint frags = min((st >> 16) + 1u, 0xffffu);
  if (count < uint(K)) {
    store_entry(px, int(count), f);
    imageStore(pstate, px, uvec4((count + 1u) | (st & 0x100u) | (frags << 16)));
    return;
  }
  Entry e[K];
  for (int i = 0; i < K; ++i) e[i] = load_entry(px, i);
  int ni = -1;
  Entry n1 = f;
  for (int i = 0; i < K; ++i)
    if (nearer(e[i], n1)) { n1 = e[i]; ni = i; }
  if (ni >= 0) { e[ni] = f; store_entry(px, ni, f); }
  int j = 0;
  for (int i = 1; i < K; ++i)
    if (nearer(e[i], e[j])) j = i;
  precise vec4 acc = imageLoad(accum, px);
  segment(acc, inside, n1, e[j]);
  imageStore(accum, px, acc);
  imageStore(pstate, px, uvec4(count | (inside ? 0x100u : 0u) | (frags << 16)));
}
