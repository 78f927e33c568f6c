// ---- raytrace_main.frag.glsl (render stage): follows the prelude and the generated
// formula block, which define zs_FGrad(p) = (grad F, F). docs/renderer.md explains the
// design; docs/camera.md the camera contract. zs_FGrad has two call sites (the sampling
// loop and the bisection loop), zs_F none and shade() one: every call site is inlined and
// multiplies llvmpipe's JIT time. No array is indexed by a run-time value: llvmpipe keeps
// constant-indexed arrays in registers but spills dynamically indexed ones to memory.

// Hierarchy: one uvec4 per node (render/hierarchy_gpu.hpp repacks the 12-float layout):
// the box as 16-bit corners on a 2^14 grid over the root box, w = escape << 1 | isLeaf.
// One fetch per visited node: on llvmpipe fetches, not arithmetic, bound the traversal.
uniform usamplerBuffer rtHierarchy;
uniform int rtNodeCount, rtFirstNode;
uniform vec3 rtRootMin, rtRootMax, rtCell;  // root box = grid extent; cell size
uniform float rtPad;
uniform vec3 rtDomainMin, rtDomainMax;
uniform vec2 rtResolution;  // full image size in pixels (tiles only restrict the scissor)
uniform vec3 rtEye, rtForward, rtRight, rtUp;
uniform float rtPlaneHalf;  // tan(fov_y/2), or height/2 when orthographic
uniform bool rtOrtho;
uniform int rtIntervals, rtMaxBisections, rtHits, rtSamples;
uniform float rtEpsilon;
uniform bool rtTangentRoots;
uniform float rtTangentTolerance;  // 1e-5 of the domain diagonal (docs/renderer.md)
uniform float rtAmbient;
uniform vec3 rtDirLightDir, rtDirLight, rtPointPos, rtPointLight;  // lights: color*intensity
uniform vec3 rtFrontColor, rtBackColor;
uniform vec2 rtFrontPhong, rtBackPhong;  // (specular, shininess)
uniform bool rtSilhouetteOn, rtBorderOn, rtReflectionOn;
uniform float rtSilhouetteThreshold, rtBorderThreshold, rtPrimaryWeight, rtOpacity;
uniform vec3 rtSilhouetteColor, rtBorderColor, rtBackground;

layout(location = 0) out vec4 rtOutColor;
layout(location = 1) out float rtOutDepth;

const int RT_SEGS = 8;         // leaf segments per ray; overflow widens the farthest
const int RT_MAX_HITS = 8;     // upper bound of tracing.hits
const int RT_MAX_EVALS = 4096; // safety bound on F evaluations per ray
const int SAMPLE = 0, BISECT_F = 1, BISECT_D = 2;  // what the sampling loop found

// Ray parameter interval inside the box [lo, hi]; empty when x > y.
vec2 slab(vec3 lo, vec3 hi, vec3 ro, vec3 inv) {
  vec3 a = (lo - ro) * inv, b = (hi - ro) * inv;
  vec3 n = min(a, b), f = max(a, b);
  return vec2(max(max(n.x, n.y), n.z), min(min(f.x, f.y), f.z));
}

// Phong with an ambient term, the directional and the point light; front faces (gradient
// against the ray) and back faces take different materials; highlights replace the color.
vec3 shade(vec3 p, vec4 g, vec3 rd) {
  float gl = length(g.xyz);
  float cosine = gl > 0.0 ? dot(g.xyz, rd) / gl : 0.0;
  bool front = cosine < 0.0;
  vec3 n = gl > 0.0 ? g.xyz / gl * (front ? 1.0 : -1.0) : -rd;
  vec3 albedo = front ? rtFrontColor : rtBackColor;
  vec2 phong = front ? rtFrontPhong : rtBackPhong;
  vec3 diffuse = vec3(rtAmbient), specular = vec3(0.0);
  for (int l = 0; l < 2; ++l) {
    vec3 L = l == 0 ? -normalize(rtDirLightDir) : normalize(rtPointPos - p);
    vec3 I = l == 0 ? rtDirLight : rtPointLight;
    float lambert = max(dot(n, L), 0.0);
    diffuse += I * lambert;
    if (lambert > 0.0)
      specular += I * phong.x * pow(max(dot(reflect(-L, n), -rd), 0.0), phong.y);
  }
  vec3 color = albedo * diffuse + specular;
  if (rtSilhouetteOn && abs(cosine) < rtSilhouetteThreshold) color = rtSilhouetteColor;
  vec3 border = min(p - rtDomainMin, rtDomainMax - p);
  if (rtBorderOn && min(min(border.x, border.y), border.z) < rtBorderThreshold)
    color = rtBorderColor;
  return clamp(color, 0.0, 1.0);
}

void main() {
  // Pixel (i, j) from the top-left of the full image (docs/camera.md).
  vec2 pixel = vec2(gl_FragCoord.x - 0.5, rtResolution.y - gl_FragCoord.y - 0.5);
  int n = max(rtSamples, 1), grid = n * n;
  // Depth comes from the pixel-center ray; an even N x N grid has none, so one more ray
  // (depth only) is traced there.
  int rays = grid + (n % 2 == 0 ? 1 : 0), centerRay = n % 2 == 0 ? grid : grid / 2;
  float alpha = clamp(rtOpacity, 0.0, 1.0), w = rtReflectionOn ? rtPrimaryWeight : 1.0;
  int hitsWanted = alpha < 1.0 ? clamp(rtHits, 1, RT_MAX_HITS) : 1;
  float depth = uintBitsToFloat(0x7F800000u);  // +inf: no hit
  vec3 sum = vec3(0.0);
  vec3 safeOne = vec3(1e-30);

  for (int s = 0; s < rays; ++s) {
    vec2 offset = s < grid ? (vec2(s % n, s / n) + 0.5) / float(n) - 0.5 : vec2(0.0);
    vec2 q = pixel + offset + 0.5;
    vec2 uv = vec2((2.0 * q.x / rtResolution.x - 1.0) * rtResolution.x / rtResolution.y,
                   1.0 - 2.0 * q.y / rtResolution.y) * rtPlaneHalf;
    vec3 ro = rtOrtho ? rtEye + uv.x * rtRight + uv.y * rtUp : rtEye;
    vec3 rd = rtOrtho ? rtForward : normalize(rtForward + uv.x * rtRight + uv.y * rtUp);
    bool colorRay = s < grid;
    vec3 color = vec3(0.0);
    float firstT = -1.0;
    vec4 firstG = vec4(0.0);

    // Pass 0: the primary ray, its hits blended front to back with the opacity (the first
    // hit weighted w when reflecting). Pass 1: one opaque reflection ray off the first hit,
    // weighted alpha * (1 - w). One loop, so the march and zs_FGrad are inlined once each.
    for (int pass = 0; pass < 2; ++pass) {
      vec3 o = ro, d = rd;
      float tStart = 0.0, passAlpha = alpha, passScale = 1.0;
      int wanted = hitsWanted;
      if (pass == 1) {
        if (!(rtReflectionOn && colorRay && firstT >= 0.0)) break;
        vec3 nrm = length(firstG.xyz) > 0.0 ? normalize(firstG.xyz) : -rd;
        o = ro + firstT * rd;
        d = reflect(rd, dot(nrm, rd) < 0.0 ? nrm : -nrm);
        tStart = max(4.0 * rtEpsilon, 1e-4 * length(rtDomainMax - rtDomainMin));  // leave the surface
        passAlpha = 1.0; passScale = alpha * (1.0 - w); wanted = 1;
      }
      float transmit = 1.0, hitT[RT_MAX_HITS];
      vec4 hitG[RT_MAX_HITS];
      int found = 0;
      vec3 inv = 1.0 / mix(d, safeOne, equal(d, vec3(0.0)));
      vec2 dom = slab(rtDomainMin, rtDomainMax, o, inv);
      // The root box holds every leaf: clipping to it here makes fetching the root (node 0)
      // unnecessary when it is an inner node (rtFirstNode = 1).
      vec2 root = slab(rtRootMin - rtPad, rtRootMax + rtPad, o, inv);
      dom = vec2(max(max(dom.x, root.x), tStart), min(dom.y, root.y));

      // Gather: stackless walk (pre-order + escape); each leaf's [t0, t1], clipped to the
      // domain, is insertion-sorted into RT_SEGS slots by compare-and-swap with constant
      // indices; once all slots are taken the farthest one widens (conservative, never a
      // miss). Overlapping slots merge when the march loads them.
      float INF = uintBitsToFloat(0x7F800000u);  // not const: GLSL 3.30 has no constant calls
      float segA[RT_SEGS], segB[RT_SEGS], segN[RT_SEGS];
      for (int m = 0; m < RT_SEGS; ++m) { segA[m] = INF; segB[m] = -INF; segN[m] = 0.0; }
      // The walk to the next leaf hit is its own light loop (llvmpipe would otherwise run
      // the insertion, masked, at every node visited).
      int count = dom.x <= dom.y ? rtNodeCount : 0, i = rtFirstNode;
      while (i < count) {
        float a = 0.0, b = 0.0;
        bool leafHit = false;
        while (i < count && !leafHit) {
          uvec4 node = texelFetch(rtHierarchy, i);
          vec3 qlo = vec3(node.x & 0xFFFFu, node.x >> 16u, node.y & 0xFFFFu);
          vec3 qhi = vec3(node.y >> 16u, node.z & 0xFFFFu, node.z >> 16u);
          vec2 tt = slab(rtRootMin + qlo * rtCell - rtPad, rtRootMin + qhi * rtCell + rtPad, o, inv);
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
          t0 = na; steps = max(1, int(nn) * rtIntervals); h = (nb - na) / float(steps);
          k = 0; havePrev = false;
        }
        int mode = SAMPLE;
        float tm = t0 + float(k) * h, ts = 0.0, fs = 0.0, ds = 0.0;
        for (; evals < RT_MAX_EVALS; ++evals) {
          vec4 g = zs_FGrad(o + tm * d);
          float f = g.w, df = dot(g.xyz, d);
          if (zs_isUndefined(f)) {
            havePrev = false;  // F's domain boundary is not the surface
          } else if (havePrev && sign(f) != sign(fa)) {
            mode = BISECT_F;
          } else if (havePrev && rtTangentRoots && fa * da < 0.0 && f * df > 0.0) {
            mode = BISECT_D;  // |F| fell, then rose
          } else {
            ta = tm; fa = f; da = df; havePrev = true;
          }
          if (mode != SAMPLE) { ts = tm; fs = f; ds = df; break; }
          if (++k > steps) break;
          tm = t0 + float(k) * h;
        }
        if (mode == SAMPLE) continue;

        float lo = ta, flo = fa, hi = ts, fhi = fs, tHit = 0.0, tSplit = 0.0, fSplit = 0.0, dSplit = 0.0;
        vec4 gHit = vec4(0.0);
        bool record = false, split = false, abandon = false;
        for (int b = 0; b < rtMaxBisections; ++b) {
          float tmid = 0.5 * (lo + hi);
          vec4 g = zs_FGrad(o + tmid * d);
          ++evals;
          float f = g.w, df = dot(g.xyz, d);
          tHit = tmid; gHit = g;
          if (zs_isUndefined(f)) { abandon = true; break; }
          if (mode == BISECT_D && sign(f) != sign(flo)) {
            // F crossed zero at the extremum: two roots. Bisect the first on F; the
            // second is found by re-sampling from here (below).
            mode = BISECT_F; split = true; tSplit = tmid; fSplit = f; dSplit = df;
          }
          if (mode == BISECT_F) {
            if (sign(f) == sign(flo)) { lo = tmid; flo = f; } else { hi = tmid; fhi = f; }
            if (f == 0.0 || hi - lo <= rtEpsilon) break;
          } else {  // sign(F_lo) * dF/dt is negative while |F| falls
            if (sign(flo) * df < 0.0) lo = tmid; else hi = tmid;
            if (hi - lo <= rtTangentTolerance) break;
          }
        }
        if (mode == BISECT_F && !abandon) {
          // One secant step inside the final bracket: depth accurate far below epsilon.
          record = true;
          if (gHit.w != 0.0) tHit = clamp(lo + (hi - lo) * flo / (flo - fhi), lo, hi);
        } else if (!abandon) {
          // A tangent root where the distance estimate |F|/|grad F| at the extremum is
          // below the tolerance: a ray grazing the surface closer than that, or touching a
          // double root (where F and grad F both vanish), hits it.
          record = abs(gHit.w) <= rtTangentTolerance * length(gHit.xyz);
        }
        if (split && !abandon) {  // re-sample [tSplit, ts] for the second root of the pair
          ta = tSplit; fa = fSplit; da = dSplit; havePrev = true;
        } else {
          ta = ts; fa = fs; da = ds; havePrev = !zs_isUndefined(fs); ++k;
        }
        if (!record) continue;
        vec3 p = o + tHit * d, slack = 1e-5 * (rtDomainMax - rtDomainMin);
        if (any(lessThan(p, rtDomainMin - slack)) || any(greaterThan(p, rtDomainMax + slack)))
          continue;  // hits count only inside the closed domain box
        for (int m = 0; m < RT_MAX_HITS; ++m) {  // constant indices: registers, not memory
          if (m == found) { hitT[m] = tHit; hitG[m] = gHit; }
        }
        if (++found >= wanted) break;
      }
      if (pass == 0 && found > 0) { firstT = hitT[0]; firstG = hitG[0]; }

      // Shade the kept hits front to back, outside the march: shade() is long and every
      // loop body runs at least once, so it runs max(found, 1) times per pass, not per round.
      for (int j = 0; j < found && colorRay; ++j) {
        float tj = 0.0;
        vec4 gj = vec4(0.0);
        for (int m = 0; m < RT_MAX_HITS; ++m) {
          if (m == j) { tj = hitT[m]; gj = hitG[m]; }
        }
        float share = (pass == 0 && j == 0) ? w : 1.0;
        color += passScale * transmit * passAlpha * share * shade(o + tj * d, gj, d);
        transmit *= 1.0 - passAlpha;
      }
      if (!colorRay) transmit = found > 0 ? 0.0 : 1.0;
      color += passScale * transmit * rtBackground;  // what the kept hits let through
    }
    if (s == centerRay && firstT >= 0.0) depth = firstT;
    if (colorRay) sum += color;
  }
  rtOutColor = vec4(sum / float(grid), 1.0);
  rtOutDepth = depth;
}
