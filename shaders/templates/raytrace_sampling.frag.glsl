// ---- raytrace_sampling.frag.glsl (render stage): the thesis' method (tracing.method =
// "sampling"), Algorithm 1 of chapter 4.4 extended: the bounding-box hierarchy is walked
// without a stack, every leaf segment is sign-sampled tracing.intervals times, sign changes
// are bisected on F and local minima of |F| on dF/dt (tangent roots). Works for every
// formula; follows raytrace_main.frag.glsl and defines its rtMarch(). zs_FGrad has two call
// sites here (the sampling loop and the bisection loop): every call site is inlined and
// multiplies llvmpipe's JIT time.

// Hierarchy: one uvec4 per node (render/hierarchy_gpu.hpp repacks the 12-float layout):
// the box as 16-bit corners on a 2^14 grid over the root box, w = escape << 1 | isLeaf.
// One fetch per visited node: on llvmpipe fetches, not arithmetic, bound the traversal.
#ifdef GL_ES
// WebGL2 has no buffer textures: the same texels in rows of RT_NODE_ROW (render/frame_uniforms.hpp).
uniform highp usampler2D rtHierarchy;
const int RT_NODE_ROW = 1024;
uvec4 rtNode(int i) { return texelFetch(rtHierarchy, ivec2(i % RT_NODE_ROW, i / RT_NODE_ROW), 0); }
#else
uniform usamplerBuffer rtHierarchy;
uvec4 rtNode(int i) { return texelFetch(rtHierarchy, i); }
#endif

const int RT_SEGS = 8;         // leaf segments per ray; overflow widens the farthest
const int RT_MAX_EVALS = 4096; // safety bound on F evaluations per ray
// What the sampling loop found: a sign change, a minimum of |F|, or a stand-in's edge
// (zs_standIns: where the product jumps, a sign change between the two samples says
// nothing, so the edge is located first and each side's signs are compared on their own).
const int SAMPLE = 0, BISECT_F = 1, BISECT_D = 2, EDGE = 3;
// Only a formula block with stand-ins defines ZS_STAND_INS: the others compile no edge code
// (llvmpipe runs every branch of the bisection loop's body, taken or not).
#ifdef ZS_STAND_INS
#define RT_STAND_INS zs_standIns
#define RT_STAND_IN_EDGE(m, ma) ((m) != (ma))
#else
#define RT_STAND_INS 0u
#define RT_STAND_IN_EDGE(m, ma) false
#endif

int rtMarch(vec3 o, vec3 d, float tStart, int wanted, out float hitT[RT_MAX_HITS],
            out vec4 hitG[RT_MAX_HITS]) {
  int found = 0;
  for (int m = 0; m < RT_MAX_HITS; ++m) { hitT[m] = 0.0; hitG[m] = vec4(0.0); }
  vec3 inv = safeInverse(d);
  // The root box holds every leaf: clipping to it here makes fetching the root (node 0)
  // unnecessary when it is an inner node (rt.firstNode = 1).
  vec2 dom = rtHitInterval(o, d, inv);
  dom.x = max(dom.x, tStart);

  // Gather: stackless walk (pre-order + escape); each leaf's [t0, t1], clipped to the
  // domain, is insertion-sorted into RT_SEGS slots by compare-and-swap with constant
  // indices; once all slots are taken the farthest one widens (conservative, never a
  // miss). Overlapping slots merge when the march loads them.
  float INF = uintBitsToFloat(0x7F800000u);  // not const: GLSL 3.30 has no constant calls
  float segA[RT_SEGS], segB[RT_SEGS], segN[RT_SEGS];
  for (int m = 0; m < RT_SEGS; ++m) { segA[m] = INF; segB[m] = -INF; segN[m] = 0.0; }
  // The walk to the next leaf hit is its own light loop (llvmpipe would otherwise run
  // the insertion, masked, at every node visited).
  int count = dom.x <= dom.y ? rt.nodeCount : 0, i = rt.firstNode;
  while (i < count) {
    float a = 0.0, b = 0.0;
    bool leafHit = false;
    while (i < count && !leafHit) {
      uvec4 node = rtNode(i);
      vec3 qlo = vec3(node.x & 0xFFFFu, node.x >> 16u, node.y & 0xFFFFu);
      vec3 qhi = vec3(node.y >> 16u, node.z & 0xFFFFu, node.z >> 16u);
      vec2 tt = slab(rt.rootMin + qlo * rt.cell - rt.pad, rt.rootMin + qhi * rt.cell + rt.pad, o, inv);
      a = max(tt.x, dom.x); b = min(tt.y, dom.y);
      bool hit = a <= b, leaf = (node.w & 1u) != 0u;
      i = (hit && !leaf) ? i + 1 : int(node.w >> 1u);
      leafHit = hit && leaf;
    }
    if (!leafHit) break;
    float ca = a, cb = b, cn = 1.0;
    for (int m = 0; m < RT_SEGS; ++m) {
      bool before = ca < segA[m];
      float xa = segA[m], xb = segB[m], xn = segN[m];
      segA[m] = before ? ca : xa; segB[m] = before ? cb : xb; segN[m] = before ? cn : xn;
      ca = before ? xa : ca; cb = before ? xb : cb; cn = before ? xn : cn;
    }
    if (ca < INF) { segB[RT_SEGS - 1] = max(segB[RT_SEGS - 1], cb); segN[RT_SEGS - 1] += cn; }
  }

  // March, thesis Algorithm 1 extended. llvmpipe runs both sides of every branch
  // (masked SIMD) and every loop body at least once per entry, so the work is split
  // into small loops: a sampling loop that walks sign samples (tracing.intervals per
  // leaf) until F changes sign or |F| has a local minimum between two samples, then
  // one bisection loop, on F (Algorithm 1) or on dF/dt (tangent roots and close root
  // pairs that sign sampling misses), then shading, once per hit.
  int k = 1, steps = 0, next = 0, evals = 0;  // k > steps: load the next segment
  float t0 = 0.0, h = 0.0;
  float ta = 0.0, fa = 0.0, da = 0.0;  // previous sample (value, derivative along d)
  uint ma = 0u;                        // and the stand-ins it took (zs_standIns)
  bool havePrev = false;
  for (int round = 0; round < 64 && evals < RT_MAX_EVALS; ++round) {
    if (k > steps) {  // the nearest slot left, merged with the slots it overlaps
      float na = INF, nb = -INF, nn = 0.0;
      for (int m = 0; m < RT_SEGS; ++m) {
        if (m == next) { na = segA[m]; nb = segB[m]; nn = segN[m]; }
        if (m > next && segA[m] <= nb) { nb = max(nb, segB[m]); nn += segN[m]; next = m; }
      }
      ++next;
      if (!(na < INF)) break;
      t0 = na; steps = max(1, int(nn) * rt.intervals); h = (nb - na) / float(steps);
      k = 0; havePrev = false;
    }
    int mode = SAMPLE;
    float tm = t0 + float(k) * h, ts = 0.0, fs = 0.0, ds = 0.0;
    uint ms = 0u;
    for (; evals < RT_MAX_EVALS; ++evals) {
      vec4 g = zs_FGrad(o + tm * d);
      float f = g.w, df = dot(g.xyz, d);
      uint m = RT_STAND_INS;
      if (zs_isUndefined(f)) {
        havePrev = false;  // F's domain boundary is not the surface
      } else if (havePrev && RT_STAND_IN_EDGE(m, ma)) {
        mode = EDGE;
      } else if (havePrev && sign(f) != sign(fa)) {
        mode = BISECT_F;
      } else if (havePrev && (rt.tangentRoots != 0) && fa * da < 0.0 && f * df > 0.0) {
        mode = BISECT_D;  // |F| fell, then rose
      } else {
        ta = tm; fa = f; da = df; ma = m; havePrev = true;
      }
      if (mode != SAMPLE) { ts = tm; fs = f; ds = df; ms = m; break; }
      if (++k > steps) break;
      tm = t0 + float(k) * h;
    }
    if (mode == SAMPLE) continue;

    float lo = ta, flo = fa, hi = ts, fhi = fs, tHit = 0.0, tSplit = 0.0, fSplit = 0.0, dSplit = 0.0;
    uint mlo = ma, mhi = ms, mSplit = 0u;
    vec4 gHit = vec4(0.0);
    bool record = false, split = false, abandon = false;
    for (int b = 0; b < rt.maxBisections; ++b) {
      float tmid = 0.5 * (lo + hi);
      vec4 g = zs_FGrad(o + tmid * d);
      ++evals;
      float f = g.w, df = dot(g.xyz, d);
      uint m = RT_STAND_INS;
      tHit = tmid; gHit = g;
      if (zs_isUndefined(f)) { abandon = true; break; }
      if (mode == BISECT_D && sign(f) != sign(flo)) {
        // F crossed zero at the extremum: two roots. Bisect the first on F; the
        // second is found by re-sampling from here (below).
        mode = BISECT_F; split = true; tSplit = tmid; fSplit = f; dSplit = df; mSplit = m;
      }
#ifdef ZS_STAND_INS
      if (mode == EDGE) {
        if (m == mlo) { lo = tmid; flo = f; } else { hi = tmid; fhi = f; mhi = m; }
        if (hi - lo <= rt.epsilon) {
          // The edge lies in [lo, hi]: a sign change before it, else one after it, is a root
          // to bisect on F; neither: none in this step (sampling goes on after it).
          bool before = sign(flo) != sign(fa);
          bool after = !before && sign(fs) != sign(fhi) && ms == mhi;
          if (!before && !after) break;
          mode = BISECT_F;
          float elo = lo, eflo = flo, ehi = hi, efhi = fhi;
          uint emlo = mlo, emhi = mhi;
          lo = before ? ta : ehi; flo = before ? fa : efhi; mlo = before ? ma : emhi;
          hi = before ? elo : ts; fhi = before ? eflo : fs; mhi = before ? emlo : ms;
        }
      } else
#endif
      if (mode == BISECT_F) {
        if (sign(f) == sign(flo)) { lo = tmid; flo = f; mlo = m; } else { hi = tmid; fhi = f; mhi = m; }
        if (f == 0.0 || hi - lo <= rt.epsilon) break;
      } else {  // sign(F_lo) * dF/dt is negative while |F| falls
        if (sign(flo) * df < 0.0) lo = tmid; else hi = tmid;
        if (hi - lo <= rt.tangentTolerance) break;
      }
    }
    if (mode == BISECT_F && !abandon) {
      // One secant step inside the final bracket: depth accurate far below epsilon. A pole
      // (1/x) changes sign too, but at a root |f(lo)| + |f(hi)| shrinks with the bracket (as
      // its width, where f is smooth) and at a pole it grows: a bracket 4 times narrower than
      // the sample step whose ends still hold half of what the samples held is no surface.
      record = !(hi - lo <= 0.25 * (ts - ta) && abs(flo) + abs(fhi) > 0.5 * (abs(fa) + abs(fs)));
      // Ends that took different stand-ins: the bracket holds a surface's domain edge, where
      // the product jumps (zs_standIns), and that is no surface either.
      record = record && !RT_STAND_IN_EDGE(mlo, mhi);
      if (gHit.w != 0.0) tHit = clamp(lo + (hi - lo) * flo / (flo - fhi), lo, hi);
    } else if (mode == BISECT_D && !abandon) {
      // A tangent root where the distance estimate |F|/|grad F| at the extremum is
      // below the tolerance: a ray grazing the surface closer than that, or touching a
      // double root (where F and grad F both vanish), hits it.
      record = abs(gHit.w) <= rt.tangentTolerance * length(gHit.xyz);
    }
    if (split && !abandon) {  // re-sample [tSplit, ts] for the second root of the pair
      ta = tSplit; fa = fSplit; da = dSplit; ma = mSplit; havePrev = true;
    } else {
      ta = ts; fa = fs; da = ds; ma = ms; havePrev = !zs_isUndefined(fs); ++k;
    }
    if (!record) continue;
    if (domainDepth(o + tHit * d) < -1e-5 * length(rt.domainMax - rt.domainMin))
      continue;  // hits count only inside the closed domain
    for (int m = 0; m < RT_MAX_HITS; ++m) {  // constant indices: registers, not memory
      if (m == found) { hitT[m] = tHit; hitG[m] = gHit; }
    }
    if (++found >= wanted) break;
  }
  return found;
}
