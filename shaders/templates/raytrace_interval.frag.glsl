// ---- raytrace_interval.frag.glsl (render stage): robust root finding for every formula
// (tracing.method = "interval", docs/renderer.md). Follows raytrace_main.frag.glsl, the
// interval prelude and the generated interval block (zs_FInterval) and defines rtFirstRoot()
// (raytrace_first_roots.frag.glsl, after it, defines rtMarch()):
//  1. The ray is clipped to the domain (box or ball) and to the box of the octree's leaves.
//  2. Its segment is classified with interval arithmetic, walking the implicit binary tree
//     of subsegments [k, k+1] 2^-level left to right with no stack (as the Bernstein method
//     does): 0 not in F(segment) proves there is no root. Where F is defined and bounded on
//     the whole segment and dF/dt keeps one sign, F is monotone: the signs of F at the two
//     ends (one new evaluation per step; the left end's value is carried) decide between no
//     root and exactly one. Otherwise the segment is halved. The first segment that holds a
//     root holds the nearest one.
//  3. Splitting stops at the pixel footprint (plus tracing.epsilon): a segment that small
//     which still cannot be decided is drawn when F is defined and bounded on it (a
//     tangency, a root of even multiplicity, a ray grazing the surface: bisected on the
//     sign change when its ends differ, its middle otherwise), and is not a surface when F
//     is unbounded or partly undefined there: poles (1/x) and the edges of sqrt's and log's
//     domains change sign without a root.
//  4. An isolated root is refined by the Illinois variant of regula falsi on F until its
//     bracket is below tracing.epsilon.
// llvmpipe runs every branch of a loop body for each group of pixels: the isolation body is
// one interval evaluation and one point evaluation, refinement has its own loop, and loops
// are do-while (a for loop runs its body once more, masked, after its last iteration).

const int RT_MAX_STEPS = 256;  // safety bound on isolation + refinement steps per segment

// The box the ray's points o + t d, t in [t0, t1], lie in, as computed in float too: the
// point evaluations at the ends must fall inside it.
void rtSegmentBox(vec3 o, vec3 d, float t0, float t1, out vec2 X, out vec2 Y, out vec2 Z) {
  vec3 a = o + t0 * d, b = o + t1 * d;
  vec3 slack = (abs(o) + abs(t0 * d) + abs(t1 * d)) * ZSI_REL + ZSI_TINY;
  vec3 lo = min(a, b) - slack, hi = max(a, b) + slack;
  X = vec2(lo.x, hi.x);
  Y = vec2(lo.y, hi.y);
  Z = vec2(lo.z, hi.z);
}

bool rtFirstRoot(vec3 o, vec3 d, float ta, float tb, out float tHit, out float tAfter) {
  float len = tb - ta;
  // A pixel's width at distance t along the ray (a constant when orthographic).
  float pixel = 2.0 * rt.planeHalf / rt.resolution.y;
  float fl = zs_F(o + ta * d), fr = 0.0;  // F at the left and right end of the segment
  bool dl = !zs_isUndefined(fl);
  bool done = !(len > 0.0), found = false, bracketed = false;
  float u = 0.0, size = 1.0;  // the tree segment [u, u + size] being classified, in [0, 1]
  int step = 0;
  do {
    float w = u + size, t0 = ta + len * u, t1 = ta + len * w;
    vec2 X, Y, Z, F, D;
    bool partial;
    rtSegmentBox(o, d, t0, t1, X, Y, Z);
    zs_FInterval(X, Y, Z, d, F, D, partial);
    fr = zs_F(o + t1 * d);
    bool dr = !zs_isUndefined(fr);
    bool none = !(F.x <= 0.0 && F.y >= 0.0);  // also F undefined everywhere (F.x > F.y)
    bool tame = !partial && F.x > -ZSI_INF && F.y < ZSI_INF;  // defined and bounded
    bool monotone = tame && (D.x > 0.0 || D.y < 0.0);
    bool known = dl && dr;
    bool signChange = known && (fl == 0.0 || fr == 0.0 || (fl > 0.0) != (fr > 0.0));
    // Where F is tame, splitting goes on to tracing.epsilon, which places a tangency or a
    // thin sheet that precisely; where it is not, it stops at the pixel footprint.
    float footprint = rt.epsilon + pixel * (rt.ortho != 0 ? 1.0 : max(t0, 0.0));
    bool small = size * len <= (tame ? rt.epsilon : footprint);
    bool root = !none && signChange && (monotone || (small && tame));
    // Undecidable that small: drawn where F is tame (header, 3.).
    bool touch = !none && !root && small && tame && !(monotone && known);
    none = none || (monotone && known && !signChange) || (small && !root && !touch);
    found = root || touch;
    bracketed = root;
    // Next: the left half of an undecided segment; after one with no root, the segment to
    // the right, which starts at w and is as large as the highest tree node starting there:
    // 2^(trailing zeros of its index at this level) times this one. Its left end's value is
    // this one's right end's.
    int index = int(w / size + 0.5);
    float climbed = size * float(index & -index);
    fl = none ? fr : fl;
    dl = none ? dr : dl;
    u = none ? w : u;
    size = found ? size : (none ? climbed : 0.5 * size);
    done = done || found || u >= 1.0;
  } while (!done && ++step < RT_MAX_STEPS);
  found = found && u < 1.0 && len > 0.0;
  float lo = u, hi = u + size, flo = fl, fhi = fr;
  float x = (bracketed && flo == 0.0) ? lo : ((bracketed && fhi == 0.0) ? hi : u + 0.5 * size);

  // Illinois: regula falsi that halves the value kept at an end chosen twice in a row, so
  // both ends of the bracket converge (superlinearly) and it ends below tracing.epsilon.
  float stop = rt.epsilon / len;
  bool refining = found && bracketed && flo != 0.0 && fhi != 0.0 && hi - lo > stop;
  int side = 0;
  do {
    if (refining) {  // the body runs once even for lanes with nothing to refine
      float xs = (lo * fhi - hi * flo) / (fhi - flo);
      xs = (xs > lo && xs < hi) ? xs : 0.5 * (lo + hi);
      float f = zs_F(o + (ta + len * xs) * d);
      f = zs_isUndefined(f) ? 0.0 : f;  // rounding off the domain inside a proven bracket
      bool left = (f > 0.0) == (flo > 0.0) && f != 0.0;
      if (left) {
        lo = xs; flo = f;
        if (side < 0) fhi *= 0.5;
        side = -1;
      } else {
        hi = xs; fhi = f;
        if (side > 0) flo *= 0.5;
        side = 1;
      }
      x = xs;
      refining = f != 0.0 && hi - lo > stop;
    }
  } while (refining && ++step < RT_MAX_STEPS);
  if (bracketed && flo != 0.0 && fhi != 0.0) x = clamp((lo * fhi - hi * flo) / (fhi - flo), lo, hi);
  tHit = ta + len * x;
  tAfter = ta + len * hi;
  return found;
}
