// ---- raytrace_main.frag.glsl (render stage): follows the prelude and the generated
// formula block, which define zs_FGrad(p) = (grad F, F). docs/renderer.md explains the
// design; docs/camera.md the camera contract. zs_FGrad has exactly ONE call site (the
// march loop): every call site is inlined and multiplies llvmpipe's JIT time.

// Hierarchy: one uvec4 per node (render/hierarchy_gpu.hpp repacks the 12-float layout):
// the box as 16-bit corners on a 2^14 grid over the root box, w = escape << 1 | isLeaf.
// One fetch per visited node: on llvmpipe fetches, not arithmetic, bound the traversal.
uniform usamplerBuffer rtHierarchy;
uniform int rtNodeCount;
uniform vec3 rtRootMin, rtCell;  // grid origin and cell size
uniform float rtPad;
uniform vec3 rtDomainMin, rtDomainMax;
uniform vec2 rtResolution;  // full image size in pixels (tiles only restrict the scissor)
uniform vec3 rtEye, rtForward, rtRight, rtUp;
uniform float rtPlaneHalf;  // tan(fov_y/2), or height/2 when orthographic
uniform bool rtOrtho;
uniform int rtIntervals, rtMaxBisections, rtHits, rtSamples;
uniform float rtEpsilon;
uniform bool rtTangentRoots;
uniform float rtAmbient;
uniform vec3 rtDirLightDir, rtDirLight, rtPointPos, rtPointLight;  // lights: color*intensity
uniform vec3 rtFrontColor, rtBackColor;
uniform vec2 rtFrontPhong, rtBackPhong;  // (specular, shininess)
uniform bool rtSilhouetteOn, rtBorderOn, rtReflectionOn;
uniform float rtSilhouetteThreshold, rtBorderThreshold, rtPrimaryWeight, rtOpacity;
uniform vec3 rtSilhouetteColor, rtBorderColor, rtBackground;

layout(location = 0) out vec4 rtOutColor;
layout(location = 1) out float rtOutDepth;

const int RT_MAX_SEGS = 16;   // merged leaf segments per ray; overflow widens a neighbour
const int RT_MAX_HITS = 8;    // upper bound of tracing.hits
const int RT_MAX_EVALS = 4096;  // safety bound on F evaluations per ray
const int SAMPLE = 0, BISECT_F = 1, BISECT_D = 2;

// Ray parameter interval inside the box [lo, hi]; empty when x > y.
vec2 slab(vec3 lo, vec3 hi, vec3 ro, vec3 inv) {
  vec3 a = (lo - ro) * inv, b = (hi - ro) * inv;
  vec3 n = min(a, b), f = max(a, b);
  return vec2(max(max(n.x, n.y), n.z), min(min(f.x, f.y), f.z));
}

// Traverses the hierarchy (stackless, pre-order + escape indices), collects the leaf
// segments in t order, merged where they overlap, then marches them: sign samples,
// bisection on F, and bisection on dF/dt where |F| has a local minimum between samples
// (tangent roots and close root pairs that pure sign sampling misses). Returns the number
// of hits (t, gradient at the hit) found, nearest first, at most `wanted`.
int traceRay(vec3 ro, vec3 rd, float tStart, int wanted, out float hitT[RT_MAX_HITS],
             out vec4 hitG[RT_MAX_HITS]) {
  for (int k = 0; k < RT_MAX_HITS; ++k) { hitT[k] = 0.0; hitG[k] = vec4(0.0); }
  vec3 safeDir = mix(rd, vec3(1e-30), equal(rd, vec3(0.0)));
  vec3 inv = 1.0 / safeDir;
  vec2 dom = slab(rtDomainMin, rtDomainMax, ro, inv);
  dom.x = max(dom.x, tStart);
  if (dom.x > dom.y || rtNodeCount == 0) return 0;

  // Segments (ta, tb, number of leaf segments merged in), sorted by t. Three float arrays,
  // not one vec3 array: Mesa 22.3 llvmpipe miscompiled the element-shifting copies
  // seg[m] = seg[m - 1] of a vector array (docs/renderer.md).
  float segA[RT_MAX_SEGS], segB[RT_MAX_SEGS], segN[RT_MAX_SEGS];
  int nseg = 0;
  for (int i = 0; i < rtNodeCount;) {
    uvec4 node = texelFetch(rtHierarchy, i);
    vec3 qlo = vec3(node.x & 0xFFFFu, node.x >> 16u, node.y & 0xFFFFu);
    vec3 qhi = vec3(node.y >> 16u, node.z & 0xFFFFu, node.z >> 16u);
    vec2 tt = slab(rtRootMin + qlo * rtCell - rtPad, rtRootMin + qhi * rtCell + rtPad, ro, inv);
    float a = max(tt.x, dom.x), b = min(tt.y, dom.y);
    bool hit = a <= b, leaf = (node.w & 1u) != 0u;
    i = (hit && !leaf) ? i + 1 : int(node.w >> 1u);
    if (!(hit && leaf)) continue;
    int k = 0;
    while (k < nseg && segB[k] < a) ++k;
    if (k < nseg && segA[k] <= b) {  // overlaps segment k: widen it, absorb followers
      segA[k] = min(segA[k], a); segB[k] = max(segB[k], b); segN[k] += 1.0;
      while (k + 1 < nseg && segA[k + 1] <= segB[k]) {
        segB[k] = max(segB[k], segB[k + 1]); segN[k] += segN[k + 1];
        for (int m = k + 1; m + 1 < nseg; ++m) {
          segA[m] = segA[m + 1]; segB[m] = segB[m + 1]; segN[m] = segN[m + 1];
        }
        --nseg;
      }
    } else if (nseg < RT_MAX_SEGS) {
      for (int m = nseg; m > k; --m) {
        segA[m] = segA[m - 1]; segB[m] = segB[m - 1]; segN[m] = segN[m - 1];
      }
      segA[k] = a; segB[k] = b; segN[k] = 1.0;
      ++nseg;
    } else {  // full: widen the neighbour with the smaller gap (conservative, never a miss)
      int m = (k == nseg || (k > 0 && a - segB[k - 1] < segA[k] - b)) ? k - 1 : k;
      segA[m] = min(segA[m], a); segB[m] = max(segB[m], b); segN[m] += 1.0;
    }
  }
  if (nseg == 0) return 0;

  int found = 0, mode = SAMPLE, si = 0, k = 0, steps = 1, bisections = 0;
  float t0 = 0.0, h = 0.0, tm = 0.0;
  float ta = 0.0, fa = 0.0, da = 0.0;  // previous sample (value, derivative along rd)
  float ts = 0.0, fs = 0.0, ds = 0.0;  // the sample that opened the current bisection
  float lo = 0.0, flo = 0.0, hi = 0.0, fhi = 0.0;
  float tSplit = 0.0, fSplit = 0.0, dSplit = 0.0;  // extremum separating a root pair
  bool havePrev = false, nextSample = false, loadSegment = true, split = false;
  for (int it = 0; it < RT_MAX_EVALS; ++it) {
    if (loadSegment) {
      if (si >= nseg) break;
      t0 = segA[si];
      steps = max(1, int(segN[si]) * rtIntervals);
      h = (segB[si] - t0) / float(steps);
      k = 0; tm = t0; havePrev = false; loadSegment = false;
    }
    vec4 g = zs_FGrad(ro + tm * rd);
    float f = g.w, df = dot(g.xyz, rd);
    bool record = false;
    float tHit = tm;
    nextSample = false;
    if (zs_isUndefined(f)) {
      // Outside F's domain: its boundary is not the surface. A bisection that runs into it
      // is abandoned and sampling resumes after the sample that opened it.
      havePrev = mode != SAMPLE;
      ta = ts; fa = fs; da = ds;
      mode = SAMPLE; split = false; nextSample = true;
    } else if (mode == SAMPLE) {
      if (f == 0.0) {
        record = true; nextSample = true; havePrev = false;
      } else if (havePrev && sign(f) != sign(fa)) {
        mode = BISECT_F; lo = ta; flo = fa; hi = tm; fhi = f;
      } else if (havePrev && rtTangentRoots && fa * da < 0.0 && f * df > 0.0) {
        mode = BISECT_D; lo = ta; flo = fa; hi = tm; fhi = f;  // |F| fell, then rose
      } else {
        ta = tm; fa = f; da = df; havePrev = true; nextSample = true;
      }
      if (mode != SAMPLE) { ts = tm; fs = f; ds = df; bisections = 0; tm = 0.5 * (lo + hi); }
    } else if (mode == BISECT_F) {  // thesis Algorithm 1 on F, bracket [lo, hi]
      ++bisections;
      if (sign(f) == sign(flo)) { lo = tm; flo = f; } else { hi = tm; fhi = f; }
      if (f == 0.0 || hi - lo <= rtEpsilon || bisections >= rtMaxBisections) {
        // One secant step inside the final bracket: depth accurate far below epsilon.
        tHit = f == 0.0 ? tm : clamp(lo + (hi - lo) * flo / (flo - fhi), lo, hi);
        record = true; mode = SAMPLE;
        if (split) {  // first root of a pair: re-sample [tSplit, ts] for the second one
          ta = tSplit; fa = fSplit; da = dSplit; havePrev = true; tm = ts; split = false;
        } else {
          ta = ts; fa = fs; da = ds; havePrev = true; nextSample = true;
        }
      } else {
        tm = 0.5 * (lo + hi);
      }
    } else {  // BISECT_D: bisection on sign(F_lo) * dF/dt, negative while |F| falls
      ++bisections;
      if (sign(f) != sign(flo)) {  // F crossed zero: two roots; bisect the first one
        mode = BISECT_F; hi = tm; fhi = f; bisections = 0;
        split = true; tSplit = tm; fSplit = f; dSplit = df;
      } else {
        if (sign(flo) * df < 0.0) lo = tm; else hi = tm;
        if (hi - lo <= rtEpsilon || bisections >= rtMaxBisections) {
          // A tangent root when F is within epsilon of zero in distance, |F|/|grad F|.
          record = abs(f) <= rtEpsilon * length(g.xyz);
          mode = SAMPLE; ta = ts; fa = fs; da = ds; havePrev = true; nextSample = true;
        }
      }
      if (mode != SAMPLE) tm = 0.5 * (lo + hi);
    }
    if (record) {
      vec3 p = ro + tHit * rd, slack = 1e-5 * (rtDomainMax - rtDomainMin);
      if (all(greaterThanEqual(p, rtDomainMin - slack)) &&
          all(lessThanEqual(p, rtDomainMax + slack)) && found < RT_MAX_HITS) {
        hitT[found] = tHit; hitG[found] = g; ++found;
        if (found >= wanted) break;
      }
    }
    if (nextSample) {
      ++k;
      if (k > steps) { ++si; loadSegment = true; } else { tm = t0 + float(k) * h; }
    }
  }
  return found;
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
  int wanted = rtOpacity < 1.0 ? clamp(rtHits, 1, RT_MAX_HITS) : 1;
  float inf = uintBitsToFloat(0x7F800000u), depth = inf;
  vec3 sum = vec3(0.0);
  for (int s = 0; s < rays; ++s) {
    vec2 offset = s < grid ? (vec2(s % n, s / n) + 0.5) / float(n) - 0.5 : vec2(0.0);
    vec2 q = pixel + offset + 0.5;
    vec2 uv = vec2((2.0 * q.x / rtResolution.x - 1.0) * rtResolution.x / rtResolution.y,
                   1.0 - 2.0 * q.y / rtResolution.y) * rtPlaneHalf;
    vec3 ro = rtOrtho ? rtEye + uv.x * rtRight + uv.y * rtUp : rtEye;
    vec3 rd = rtOrtho ? rtForward : normalize(rtForward + uv.x * rtRight + uv.y * rtUp);
    bool colorRay = s < grid;

    // Pass 0: the primary ray; pass 1: one reflection ray off the first hit. One loop, so
    // traceRay (and zs_FGrad inside it) is inlined once.
    float primT[RT_MAX_HITS], passT[RT_MAX_HITS];
    vec4 primG[RT_MAX_HITS], passG[RT_MAX_HITS];
    int primCount = 0, reflCount = 0;
    vec3 reflO = vec3(0.0), reflD = vec3(0.0);
    vec4 reflG = vec4(0.0);
    float reflT = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
      bool reflect1 = pass == 1;
      if (reflect1 && !(rtReflectionOn && colorRay && primCount > 0)) break;
      vec3 o = ro, d = rd;
      float tStart = 0.0;
      if (reflect1) {
        vec3 nrm = length(primG[0].xyz) > 0.0 ? normalize(primG[0].xyz) : -rd;
        o = ro + primT[0] * rd;
        d = reflect(rd, dot(nrm, rd) < 0.0 ? nrm : -nrm);
        // Leave the surface before looking for the next hit.
        tStart = max(4.0 * rtEpsilon, 1e-4 * length(rtDomainMax - rtDomainMin));
        reflO = o; reflD = d;
      }
      int count = traceRay(o, d, tStart, reflect1 ? 1 : wanted, passT, passG);
      if (reflect1) {
        reflCount = count; reflT = passT[0]; reflG = passG[0];
      } else {
        primCount = count; primT = passT; primG = passG;
      }
    }
    if (s == centerRay && primCount > 0) depth = primT[0];
    if (!colorRay) continue;

    vec3 reflColor = reflCount > 0 ? shade(reflO + reflT * reflD, reflG, reflD) : rtBackground;
    // Front-to-back blending of the kept hits with the opacity; opaque stops at the first.
    vec3 color = vec3(0.0);
    float transmit = 1.0, alpha = clamp(rtOpacity, 0.0, 1.0);
    for (int k = 0; k < primCount; ++k) {
      vec3 c = shade(ro + primT[k] * rd, primG[k], rd);
      if (k == 0 && rtReflectionOn) c = mix(reflColor, c, rtPrimaryWeight);
      color += transmit * alpha * c;
      transmit *= 1.0 - alpha;
    }
    sum += color + transmit * rtBackground;
  }
  rtOutColor = vec4(sum / float(grid), 1.0);
  rtOutDepth = depth;
}
