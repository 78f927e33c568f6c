// ---- raytrace_bernstein.frag.glsl (render stage): exact root isolation for polynomial F
// (tracing.method = "bernstein", docs/renderer.md). Follows raytrace_main.frag.glsl and the
// generated ray polynomial block (zs_FPoly and the Bernstein kernels of degree zs_DEGREE)
// and defines rtMarch():
//  1. The octree's cells are visited front to back without a stack: the cell holding the
//     ray just after t is found by descending from the root, choosing each child by
//     comparing t with the ray parameters of the parent's mid-planes, so a cell boundary is
//     decided by the very same float comparison on both of its sides (no gaps, no repeats).
//     Empty cells are skipped whole; the walk stops at the first leaf holding a root.
//  2. In a leaf segment [ta, tb], f(s) = F(o + (ta + s (tb - ta)) d) comes from one call of
//     zs_FPoly, in the Bernstein basis on [0, 1]. Its coefficients bound f (convex hull) and
//     their sign changes V bound the number of roots (Descartes): V = 1, or a monotone f
//     (no sign change among the derivative's coefficients) with a sign change, isolates
//     exactly one root; no coefficient of one sign proves there is none. Otherwise the
//     interval is halved, walking the implicit binary tree of subintervals [k, k+1] 2^-level
//     left to right without a stack: each visited node's coefficients are restricted from
//     the segment's by de Casteljau, so nothing is kept per level.
//  3. An isolated root is refined by regula falsi with the Illinois modification, which
//     keeps a bracket, to tracing.epsilon, then one secant step inside the final bracket.
//  4. An interval narrower than the tangent tolerance (1e-5 of the domain diagonal) that
//     still cannot be decided holds a root of even multiplicity, a cluster of roots, or a
//     ray passing closer than that to the surface: it is a hit (a ray touching a sphere,
//     the squared sphere (x^2+y^2+z^2-1)^2). Nothing is ever skipped that may hold a root.

// The octree (render/octree_gpu.hpp): inner nodes, two words each:
//   x = existing children (bit k for octant k = x | y << 1 | z << 2) | leaf children << 8,
//   y = index of the first inner child; the inner children follow in octant order.
uniform usamplerBuffer rtOctree;
uniform uvec2 rtOctreeRoot;     // node 0, so the first level costs no fetch
uniform bool rtOctreeRootLeaf;  // the whole box is one leaf
uniform vec3 rtOctreeMin, rtOctreeExtent;

const int RT_MAX_LEVEL = 20;       // the octree's deepest level (interval/octree.hpp)
const int RT_MAX_CELLS = 4096;     // safety bound on cells visited per ray
const int RT_MAX_ISOLATION = 160;  // safety bound on subintervals visited per segment

uint rtPopcount8(uint x) {
  x = x - ((x >> 1u) & 0x55u);
  x = (x & 0x33u) + ((x >> 2u) & 0x33u);
  return (x + (x >> 4u)) & 0x0Fu;
}

// The cell holding the ray o + t' d for t' just above t: returns the ray parameter where it
// leaves that cell; `leaf` tells a leaf (may hold the surface) from an empty cell. Planes
// are min + k 2^-level extent, a single rounding of the same real wherever a plane is met,
// so the exit of one cell is exactly the entry the next descent compares against.
float rtCellExit(vec3 o, vec3 inv, float t, out bool leaf) {
  leaf = rtOctreeRootLeaf;
  if (leaf) return uintBitsToFloat(0x7F800000u);
  uvec2 node = rtOctreeRoot;
  uvec3 cell = uvec3(0u);
  bvec3 forward = greaterThan(inv, vec3(0.0));
  float tExit = t;
  for (int level = 1; level <= RT_MAX_LEVEL; ++level) {
    vec3 size = rtOctreeExtent * exp2(-float(level));
    vec3 tMid = (rtOctreeMin + vec3(2u * cell + 1u) * size - o) * inv;
    // Upper half along an axis: beyond the mid-plane going forward, before it going back.
    bvec3 upper = equal(greaterThanEqual(vec3(t), tMid), forward);
    uvec3 child = 2u * cell + uvec3(upper);
    vec3 tFar = (rtOctreeMin + vec3(child + uvec3(forward)) * size - o) * inv;
    tExit = min(min(tFar.x, tFar.y), tFar.z);
    uint bit = 1u << (uint(upper.x) | uint(upper.y) << 1u | uint(upper.z) << 2u);
    leaf = (node.x & (bit << 8u)) != 0u;
    if ((node.x & bit) == 0u || leaf) break;
    uint inner = node.x & ~(node.x >> 8u) & 0xFFu;
    node = texelFetch(rtOctree, int(node.y + rtPopcount8(inner & (bit - 1u)))).xy;
    cell = child;
  }
  return tExit;
}

// The first root of F on the ray o + t d with t in [ta, tb] (item 2-4 above). On success
// tHit is the root and tAfter the end of its bracket: no other root lies in (tHit, tAfter].
bool rtFirstRoot(vec3 o, vec3 d, float ta, float tb, out float tHit, out float tAfter) {
  tHit = ta;
  tAfter = tb;
  float len = tb - ta;
  float c[zs_N], b0[zs_N], b[zs_N];
  if (!(len > 0.0) || !zs_FPoly(o + ta * d, len * d, c)) return false;
  zs_toBernstein(c, b0);

  float tolerance = rtTangentTolerance / len;  // in units of s
  int level = 0, index = 0, outcome = 0;       // outcome: 0 none, 1 bracket, 2 cluster
  float u = 0.0, w = 1.0;
  for (int it = 0; it < RT_MAX_ISOLATION; ++it) {
    float size = exp2(-float(level));
    u = float(index) * size;
    w = float(index + 1) * size;
    zs_restrict(b0, u, w, b);
    vec4 k = zs_classify(b);  // (min, max, V, V of the derivative)
    bool none = !(k.x <= 0.0 && k.y >= 0.0);  // also NaN (overflow): nothing to find
    bool monotone = k.w == 0.0;
    if (!none && monotone && (b[0] > 0.0) == (b[zs_DEGREE] > 0.0) && b[0] != 0.0 &&
        b[zs_DEGREE] != 0.0)
      none = true;  // monotone without a sign change
    if (!none && (k.z == 1.0 || monotone)) { outcome = 1; break; }
    if (!none && size <= tolerance) { outcome = 2; break; }
    if (!none) {  // descend to the left half
      ++level;
      index *= 2;
      continue;
    }
    // Next interval to the right: climb while a right child, then step to the sibling.
    int next = index + 1;
    int climb = (floatBitsToInt(float(next & -next)) >> 23) - 127;  // trailing zeros
    level -= climb;
    index = next >> climb;
    if (level <= 0) break;
  }
  if (outcome == 0) return false;

  float lo = 0.0, hi = 1.0, sHit = 0.5;
  if (outcome == 1) {
    float flo = b[0], fhi = b[zs_DEGREE];  // true values at the bracket's ends
    float wlo = flo, whi = fhi;            // Illinois-weighted values
    float stop = rtEpsilon / (len * (w - u));
    int side = 0;
    for (int it = 0; it < rtMaxBisections && hi - lo > stop; ++it) {
      float r = (lo * whi - hi * wlo) / (whi - wlo);
      if (!(r > lo && r < hi)) r = 0.5 * (lo + hi);
      float fr = zs_bernsteinAt(b, r);
      if (fr == 0.0) { lo = r; hi = r; flo = 0.0; fhi = 0.0; break; }
      if ((fr > 0.0) == (flo > 0.0)) {
        lo = r; flo = fr; wlo = fr;
        if (side < 0) whi *= 0.5;
        side = -1;
      } else {
        hi = r; fhi = fr; whi = fr;
        if (side > 0) wlo *= 0.5;
        side = 1;
      }
    }
    sHit = fhi != flo ? clamp((lo * fhi - hi * flo) / (fhi - flo), lo, hi) : lo;
  } else {
    hi = 1.0;
  }
  tHit = ta + len * (u + (w - u) * sHit);
  tAfter = ta + len * (u + (w - u) * hi);
  return true;
}

int rtMarch(vec3 o, vec3 d, float tStart, int wanted, out float hitT[RT_MAX_HITS],
            out vec4 hitG[RT_MAX_HITS]) {
  for (int m = 0; m < RT_MAX_HITS; ++m) { hitT[m] = 0.0; hitG[m] = vec4(0.0); }
  vec3 inv = safeInverse(d);
  vec2 dom = slab(rtDomainMin, rtDomainMax, o, inv);
  vec2 box = slab(rtOctreeMin, rtOctreeMin + rtOctreeExtent, o, inv);
  float t = max(max(dom.x, box.x), tStart), tEnd = min(dom.y, box.y);
  int found = 0;
  for (int step = 0; step < RT_MAX_CELLS && t < tEnd; ++step) {
    bool leaf;
    float tExit = min(rtCellExit(o, inv, t, leaf), tEnd);
    float tHit, tAfter;
    if (leaf && rtFirstRoot(o, d, t, tExit, tHit, tAfter)) {
      vec4 g = zs_FGrad(o + tHit * d);
      for (int m = 0; m < RT_MAX_HITS; ++m) {  // constant indices: registers, not memory
        if (m == found) { hitT[m] = tHit; hitG[m] = g; }
      }
      if (++found >= wanted) break;
      tExit = tAfter;  // the next root lies beyond the bracket of this one
    }
    t = tExit > t ? tExit : t + 1e-6 * (tEnd - t);  // always advance, even on a degenerate cell
  }
  return found;
}
