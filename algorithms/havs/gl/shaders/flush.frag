// Flush pass: kbuffer_flush, the remaining entries nearest first (after common.glsl).
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  uint st = imageLoad(pstate, px).x;
  int count = int(st & 0xffu);
  bool inside = (st & 0x100u) != 0u;
  if (count < 2) return;
  Entry e[K];
  for (int i = 0; i < K; ++i)
    if (i < count) e[i] = load_entry(px, i);
  precise vec4 acc = imageLoad(accum, px);
  // kbuffer_flush: pop the nearest, composite it with the next nearest.
  while (count >= 2) {
    int i = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[i])) i = q;
    Entry n1 = e[i];
    --count;
    e[i] = e[count];
    int j = 0;
    for (int q = 1; q < count; ++q)
      if (nearer(e[q], e[j])) j = q;
    segment(acc, inside, n1, e[j]);
  }
  imageStore(accum, px, acc);
}
