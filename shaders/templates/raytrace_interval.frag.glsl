// ---- raytrace_interval.frag.glsl (render stage): robust root finding for every formula
// (tracing.method = "interval", docs/renderer.md). Follows raytrace_main.frag.glsl, the
// interval and affine preludes and the generated interval block (zs_FAffine) and defines
// rtFirstRoot() (raytrace_first_roots.frag.glsl, after it, defines rtMarch()):
//  1. The ray is clipped to the domain (box or ball) and to the box of the octree's leaves.
//  2. Its segment is classified front to back, one subsegment [u, v] at a time, with F and
//     dF/dt as affine forms along it (affine_prelude.frag.glsl: F(t) lies in c + s tau +- r,
//     tau in [-1, 1]): 0 not in the form's range proves there is no root. Where F is
//     defined and bounded on the whole segment and dF/dt keeps one sign, F is monotone: the
//     signs of F at the two ends decide between no root and exactly one. Those signs come
//     from the form itself, which proves the sign of c + s tau outside the window where
//     |c + s tau| <= r can hold (the left end's sign is also carried from the segment
//     before); F is not evaluated at the ends, which took a tenth of the walk's work.
//     A monotone segment whose window covers its right end holds a root only near that end:
//     next comes the segment from the window on, twice as long as what of it lay inside.
//     Otherwise the segment is clipped to that window (roots lie nowhere else), or halved
//     where that keeps more than half of it, or quartered where the remainder r dwarfs the
//     slope s (the form is far from first-order tight, and r shrinks with the square of the
//     length). Where a clip cuts a segment's right end, the part cut off is free of roots:
//     the walk jumps over it once it gets there (the bumpy sphere's reflection rays took
//     5 % fewer steps). After a segment with no root comes the one to its right, as much
//     longer as its form predicts it can still clear (half that guess, 1.5 to 8 times; 2 to
//     8 for a reflection ray).
//     Only segments proven free of roots are passed, so the first segment that holds a root
//     holds the nearest.
//  3. Splitting stops at the pixel footprint (plus tracing.epsilon): a segment that small
//     which still cannot be decided is drawn when F is defined and bounded on it (a
//     tangency, a root of even multiplicity, a ray grazing the surface: bisected on the
//     sign change when its ends differ, its middle otherwise), and is not a surface when F
//     is unbounded or partly undefined there: poles (1/x) and the edges of sqrt's and log's
//     domains change sign without a root.
//  4. An isolated root is refined by the Illinois variant of regula falsi on F until its
//     bracket is below tracing.epsilon, from the part of its segment where the form allows
//     a root, or until F at the latest point x pins it nearer: on a monotone segment
//     |dF/dt| lies between m and M (dF/dt's range), so the root lies between |F(x)| / M and
//     |F(x)| / m from x, on the side of the sign change.
//  5. The first segment is rtFirstSegment long (raytrace_main.frag.glsl): for a primary ray
//     8 times the last segment of its tile's beam (raytrace_beam.frag.glsl), which also moved
//     the ray's start; for a reflection ray the width of the segment that isolated the primary
//     hit (rtIsolatedWidth): a scale at which the walk could decide F near there.
// llvmpipe runs every branch of a loop body for each group of pixels: the isolation body is
// one affine evaluation, refinement has its own loop, and loops are do-while (a for loop
// runs its body once more, masked, after its last iteration).

const int RT_MAX_STEPS = 256;  // safety bound on isolation + refinement steps per segment
// The next segment after one without root: the predicted growth (below) times this, at most
// RT_GROWTH_MAX, at least rtGrowth. Half the prediction, because a segment that grows too far
// fails to clear and is split again, which costs more than the step it would save
// (docs/renderer.md, "The interval method", 2.).
const float RT_GROWTH_TRUST = 0.5, RT_GROWTH_MAX = 8.0;

// The half-width h of t = tm + h tau, tau in [-1, 1], that covers [t0, t1] as rounded
// (tm = (t0 + t1) / 2 in float).
float rtHalfWidth(float t0, float t1, float tm) {
  return (0.5 * t1 - 0.5 * t0) * (1.0 + ZSI_REL) + abs(tm) * ZSI_REL + ZSI_TINY;
}

// Where |c + s tau| <= r can hold for the form F = (c, s, r), s != 0: the tau window, widened
// by 1/32 of itself and by the rounding of tau <-> t (t values of magnitude tScale), so that
// the form alone proves F's sign just outside it. Roots lie nowhere else (header, 2.; the
// beam pass clips with it too).
vec2 rtZeroWindow(vec3 F, float h, float tScale) {
  float q1 = (-F.z - F.x) / F.y, q2 = (F.z - F.x) / F.y;
  float lo = min(q1, q2), hi = max(q1, q2);
  float margin = (hi - lo) * 0.03125 + (abs(q1) + abs(q2)) * ZSI_REL +
                 tScale * (8.0 * ZSI_REL) / h;
  return vec2(lo - margin, hi + margin);
}

bool rtFirstRoot(vec3 o, vec3 d, float ta, float tb, out float tHit, out float tAfter) {
  float len = tb - ta;
  // A pixel's width at distance t along the ray (a constant when orthographic).
  float pixel = 2.0 * rt.planeHalf / rt.resolution.y;
  // F at the left end u of the segment, carried from the segment before (evaluated at the
  // ray's start), and at its right end v (the form's c + s tau): only their signs, which are
  // proven where carriedKnown / knownAtV say so, and rough sizes count.
  float fCarried = zs_F(o + ta * d), fAtV = 0.0;
  bool carriedKnown = !zs_isUndefined(fCarried);
  bool done = !(len > 0.0), found = false, bracketed = false;
  // The segment [u, v] being classified, in [0, 1]; the first one as long as the hint (5.).
  float u = 0.0, v = clamp(rtFirstSegment / len, 0.0, 1.0);
  // tracing.epsilon in units of the segment: the smallest step forward after a segment
  // without root, and the width refinement stops at.
  float least = rt.epsilon / len;
  // Bounds of |dF/du| on the segment that isolated the root (0 and inf: none): refinement.
  float slopeMin = 0.0, slopeMax = ZSI_INF;
  // A stretch (gapFrom, gapTo] that a form proved free of roots when it clipped its
  // segment's right end, with the form's value at gapTo (its sign is proven): the walk
  // jumps over it when it gets there instead of walking it again.
  float gapFrom = 2.0, gapTo = 2.0, gapValue = 0.0;
  int step = 0;
  do {
    // Redundant by GLSL's rules, needed on llvmpipe (Mesa 22.3): without it, lanes that had
    // isolated their root in a window clipped at both ends left the loop with found and
    // bracketed cleared but u at that window (traced on the bumpy sphere at 200 x 200, where
    // 65 silhouette pixels were missed), as if the body had run on for them while other
    // lanes of their group walked on. The guard costs nothing: both sides of a branch run.
    if (!done) {
      float t0 = ta + len * u, t1 = ta + len * v;
      float tm = 0.5 * t0 + 0.5 * t1, h = rtHalfWidth(t0, t1, tm);
      vec3 F;
      vec2 D;
      bool partial;
      zs_FAffine(o, d, tm, h, F, D, partial);
      vec2 range = zsa_range(F);
      bool none = !(range.x <= 0.0 && range.y >= 0.0);  // also F undefined everywhere
      bool tame = !partial && range.x > -ZSI_INF && range.y < ZSI_INF;  // defined and bounded
      bool monotone = tame && (D.x > 0.0 || D.y < 0.0);
      slopeMin = monotone ? len * min(abs(D.x), abs(D.y)) : 0.0;
      slopeMax = len * max(abs(D.x), abs(D.y));
      bool sloped = tame && !none && F.y != 0.0;
      vec2 window = sloped ? rtZeroWindow(F, h, abs(tm) + abs(ta) + len) : vec2(-2.0, 2.0);
      // F's signs at the ends from the form alone: where it clears the segment, c's; else,
      // outside the window, those of c + s tau.
      bool cleared = none && range.x <= range.y;
      fAtV = F.x + F.y;
      bool knownAtV = cleared || (sloped && window.y < 1.0);
      float fAtU = carriedKnown ? fCarried : F.x - F.y;
      bool knownAtU = carriedKnown || cleared || (sloped && window.x > -1.0);
      bool known = knownAtU && knownAtV;
      bool signChange = known && (fAtU == 0.0 || (fAtU > 0.0) != (fAtV > 0.0));
      // Where F is tame, splitting goes on to tracing.epsilon, which places a tangency or a
      // thin sheet that precisely; where it is not, it stops at the pixel footprint.
      float footprint = rt.epsilon + pixel * (rt.ortho != 0 ? 1.0 : max(t0, 0.0));
      float size = v - u;
      rtIsolatedWidth = size * len;  // the last segment's: the one that isolated the root
      bool small = size * len <= (tame ? rt.epsilon : footprint);
      bool root = !none && signChange && (monotone || (small && tame));
      // Undecidable that small: drawn where F is tame (header, 3.).
      bool touch = !none && !root && small && tame && !(monotone && known);
      none = none || (monotone && known && !signChange) || (small && !root && !touch);
      found = root || touch;
      bracketed = root;
      // Clipping (header, 2.): roots lie only where |c + s tau| <= r. The new ends are pulled
      // out by a margin that covers the rounding of tau <-> t <-> u, so that the form alone
      // proves F's sign there: F(new left end) has the sign of c + s tau, which is kept as its
      // value (Illinois needs only its sign and a rough size).
      // A root isolated on a monotone segment lies in that window too: its ends, with the
      // form's values there (whose signs the form proves), become the bracket refinement
      // starts from, so a tight form leaves little to refine.
      float clipU = u, clipV = v, clipFU = fAtU, clipFV = fAtV;
      if (sloped && !touch) {
        float lo = window.x, hi = window.y;
        float ul = (tm + h * lo - ta) / len, uh = (tm + h * hi - ta) / len;
        float value = F.x + F.y * lo, high = F.x + F.y * hi;
        if (ul > u && lo > -1.0 && value != 0.0) { clipU = ul; clipFU = value; }
        if (uh < v && hi < 1.0 && high != 0.0) {
          clipV = uh; clipFV = high;
          bool joins = v >= gapFrom;  // (uh, v] and the gap before make one stretch
          gapValue = (joins && gapTo > v) ? gapValue : fAtV;  // the form at v
          gapTo = joins ? max(gapTo, v) : v;
          gapFrom = uh;
        }
        // The clipped range misses [u, v] (it lies in the rounding slack of tm +- h); a root
        // whose window collapsed that way keeps its segment.
        none = none || (!found && !(clipU < clipV));
        if (root && !(clipU < clipV)) { clipU = u; clipV = v; clipFU = fAtU; clipFV = fAtV; }
      }
      // Next: after a segment with no root, the one to its right, longer by the growth below;
      // else the clipped segment, or the left half of it where clipping gained less than half.
      float kept = clipV - clipU;
      // Where the remainder dwarfs the slope the form is far from first-order tight (it
      // shrinks with the square of the length): a quarter.
      float part = F.z > 2.0 * abs(F.y) ? 0.25 : 0.5;
      // Monotone with the window over the right end: a root lies only near that end, inside or
      // just past it: the segment from the window on, twice as long as what of it was inside.
      bool straddle = monotone && !knownAtV && !found && !none && kept < 0.5 * size;
      clipV = straddle ? min(1.0, clipU + 2.0 * kept)
                       : ((!found && kept > 0.5 * size) ? clipU + part * kept : clipV);
      fCarried = none ? fAtV : (clipU > u ? clipFU : fAtU);
      fAtV = root ? clipFV : fAtV;
      carriedKnown = none ? knownAtV : (knownAtU || clipU > u);
      u = none ? v : clipU;
      // How much longer the next segment may be and still be cleared by its form, predicted
      // from this one's: with e = c + s (the form at the right end), the next segment g times
      // as long has its center near e + g s, slope g s and remainder g^2 r, which keeps F's
      // sign while |e| - a g - r g^2 > 0, a = |s| - s sgn(e); g is growthGuess. Only a guess
      // (any growth is exact): never below rtGrowth (raytrace_main.frag.glsl sets it per ray
      // and says why); a NaN guess gives rtGrowth.
      float e = F.x + F.y, absE = abs(e), a = abs(F.y) - F.y * sign(e);
      float growthGuess = RT_GROWTH_TRUST * 2.0 * absE / (a + sqrt(a * a + 4.0 * absE * F.z));
      float growth = (tame && growthGuess > rtGrowth) ? min(growthGuess, RT_GROWTH_MAX) : rtGrowth;
      v = none ? min(1.0, v + max(growth * size, least)) : clipV;
      bool jump = none && u >= gapFrom && u < gapTo;
      v = jump ? min(1.0, gapTo + (v - u)) : v;
      fCarried = jump ? gapValue : fCarried;
      carriedKnown = carriedKnown || jump;
      u = jump ? gapTo : u;
      done = done || found || u >= 1.0;
    }
  } while (!done && ++step < RT_MAX_STEPS);
  found = found && u < 1.0 && len > 0.0;
  float lo = u, hi = v, flo = fCarried, fhi = fAtV;
  float x = (bracketed && flo == 0.0) ? lo : ((bracketed && fhi == 0.0) ? hi : 0.5 * (u + v));

  // Illinois: regula falsi that halves the value kept at an end chosen twice in a row, so
  // both ends of the bracket converge (superlinearly) and it ends below tracing.epsilon.
  bool refining = found && bracketed && flo != 0.0 && fhi != 0.0 && hi - lo > least;
  int side = 0;
  bool pinned = false;
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
      // The root lies between |f| / slopeMax and |f| / slopeMin from xs, on the side of the sign
      // change: once that pins it to within tracing.epsilon, its middle is the hit.
      float near = abs(f) / slopeMax, far = abs(f) / slopeMin;
      float a = left ? max(lo, xs + near) : max(lo, xs - far);
      float b = left ? min(hi, xs + far) : min(hi, xs - near);
      pinned = b - a <= least;
      x = pinned ? 0.5 * (a + b) : xs;
      refining = f != 0.0 && hi - lo > least && !pinned;
    }
  } while (refining && ++step < RT_MAX_STEPS);
  if (bracketed && !pinned && flo != 0.0 && fhi != 0.0)
    x = clamp((lo * fhi - hi * flo) / (fhi - flo), lo, hi);
  tHit = ta + len * x;
  tAfter = ta + len * hi;
  return found;
}
