// ---- raytrace_first_roots.frag.glsl (render stage): rtMarch() for the methods that find the
// first root of a ray segment, raytrace_bernstein.frag.glsl and raytrace_interval.frag.glsl,
// which come before this file and define
//   bool rtFirstRoot(vec3 o, vec3 d, float ta, float tb, out float tHit, out float tAfter);
// (the nearest root in [ta, tb], false if none; tAfter: where the segment holds no other
// root before). The ray is clipped to the domain (box or ball) and to the box of the
// octree's leaves; the gradient is evaluated once per hit, for shading.

int rtMarch(vec3 o, vec3 d, float tStart, int wanted, out float hitT[RT_MAX_HITS],
            out vec4 hitG[RT_MAX_HITS]) {
  for (int m = 0; m < RT_MAX_HITS; ++m) { hitT[m] = 0.0; hitG[m] = vec4(0.0); }
  vec3 inv = safeInverse(d);
  vec2 clip = rtHitInterval(o, d, inv);
  float t = max(clip.x, tStart), tEnd = clip.y;
  int found = 0;
#if RT_MAX_HITS == 1
  float tHit, tAfter;
  if (rtFirstRoot(o, d, t, tEnd, tHit, tAfter) && t < tEnd) {
    found = 1;
    hitT[0] = tHit;
  }
  hitG[0] = zs_FGrad(o + hitT[0] * d);
#else
  // Further hits: the segment restarts past the bracket of the last root (it holds no other).
  for (int k = 0; k < RT_MAX_HITS && k < wanted && t < tEnd; ++k) {
    float tHit, tAfter;
    if (!rtFirstRoot(o, d, t, tEnd, tHit, tAfter)) break;
    vec4 g = zs_FGrad(o + tHit * d);
    for (int m = 0; m < RT_MAX_HITS; ++m) {  // constant indices: registers, not memory
      if (m == found) { hitT[m] = tHit; hitG[m] = g; }
    }
    ++found;
    // Past the tolerance too: a restart right at a root could find that root again.
    t = max(max(tAfter, tHit + rt.tangentTolerance), t + 1e-6 * (tEnd - t));
  }
#endif
  return found;
}
