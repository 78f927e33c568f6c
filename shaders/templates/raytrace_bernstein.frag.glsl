// ---- raytrace_bernstein.frag.glsl (render stage): exact root isolation for polynomial F
// (tracing.method = "bernstein", docs/renderer.md). Follows raytrace_main.frag.glsl and the
// generated ray polynomial block (zs_FPoly and the Bernstein kernels of degree zs_DEGREE)
// and defines rtFirstRoot() (raytrace_first_roots.frag.glsl, after it, defines rtMarch()):
//  1. The ray is clipped to the domain (box or ball) and to the box of the octree's leaves. On that
//     segment f(s) = F(o + t(s) d), s in [0, 1], comes from ONE call of zs_FPoly (a Taylor
//     expansion about the segment's midpoint, in double), in the Bernstein basis.
//  2. The Bernstein coefficients bound f on an interval (convex hull) and their sign changes
//     V bound its number of roots (Descartes): ends of proven opposite signs with V = 1, or
//     with a monotone f (no sign change among the derivative's coefficients), isolate one
//     root; every coefficient beyond the noise band on one side proves there is none.
//     Otherwise the interval is halved, walking the implicit binary tree of intervals
//     [k, k+1] 2^-level left to right with no stack, from the segment's two halves. The walk
//     keeps f on the rest [u, 1] of the window: one de Casteljau pass (zs_split) gives the
//     visited interval and the rest after it, so nothing is kept per level. The first
//     interval that holds a root holds the nearest one.
//  3. The isolated root is refined from where the control polygon crosses 0 by Halley steps
//     safeguarded by bisection inside its bracket until a step is below tracing.epsilon / 16;
//     f, f' and f'' come from the Taylor coefficients by Horner (3D multiply-adds, against
//     D^2 for a de Casteljau pass).
//  4. Rounding: every sign decision is made against a noise band that bounds what rounding
//     can have done to a coefficient (the expansion's a priori error bound, the one rounding
//     of its result to zs_Real, the de Casteljau passes). An interval narrower than the
//     tangent tolerance (1e-5 of the domain diagonal) that still cannot be decided by an
//     expansion no longer than a few tolerances holds a root of even multiplicity, a
//     cluster of roots, or a ray passing closer than rounding can tell from touching: it is
//     a hit (a ray touching a sphere, the squared sphere (x^2+y^2+z^2-1)^2).
//  5. Re-expansion: the noise band is relative to the largest coefficient of the window,
//     which grows with the window's length. Where it cannot decide (an undecided interval
//     whose coefficients all lie inside the band, or one narrower than the tolerance), f is
//     expanded anew about that interval alone, whose coefficients are those of f near there,
//     and the walk goes on in it; after a window with no root, the rest of the segment is
//     expanded anew. So a hit stands on a proven root, or on f within rounding of 0 over a
//     stretch narrower than the tolerance where f is expanded about that stretch itself.
// llvmpipe runs every branch of a loop body for each group of pixels: the isolation loop's
// body makes exactly one zs_split call, refinement has a loop of its own (sharing one
// loop made every refinement step pay for a pass), and loops are do-while (a for loop
// runs its body once more, masked, after its last iteration).


// What rounding can have done to any coefficient of an interval split off the window's
// coefficients by up to two de Casteljau passes (4.): the Taylor arithmetic and the conversion in
// zs_Wide (a priori, from the absolute-value bound), the one rounding to zs_Real, and the
// passes (convex combinations: a few roundings of the largest coefficient each; the walk
// adds one pass's worth for each interval it splits off the rest). A volume's windows use
// it too (raytrace_volume.frag.glsl). maxAbs: zs_maxAbs of the window's coefficients.
zs_Real rtNoise(zs_Bound bound, zs_Real maxAbs) {
  return max(zs_Real(zs_ROUNDINGS * zs_WIDE_EPS * bound) +
                 zs_EPS * zs_Real(8 * zs_DEGREE + 2) * maxAbs,
             zs_NOISE_FLOOR);
}

const int RT_MAX_STEPS = 1000;  // safety bound on isolation + refinement steps per segment
const int RT_MAX_WINDOWS = 48;  // safety bound on expansions per segment (5.)

bool rtFirstRoot(vec3 o, vec3 d, float ta, float tb, out float tHit, out float tAfter) {
  // float, or double for high degrees (emit_ray_polynomial.hpp kDoubleDegree)
  zs_Real c[zs_N], b[zs_N];
  // The window [wa, wb] of the segment that the current expansion covers (5.).
  float wa = ta, wb = tb, len = tb - ta;
  bool done = !(len > 0.0), found = false, isolated = false;
  float u = 0.0, size = 1.0;  // the tree interval [u, u + size] of the window being classified
  int step = 0, windows = 0;
  do {
    // Redundant in GLSL, needed on llvmpipe: without it a lane that had found its root in one
    // window had `found` cleared while other lanes of its group walked later windows (docs/
    // renderer.md, "Mesa 22.3 llvmpipe problems").
    if (!done) {
      len = wb - wa;
      zs_Wide wide[zs_N];  // double, or double-float in GLSL ES (emit_ray_polynomial.hpp)
      zs_Bound bound;
      bool defined = zs_FPolyOn(o, d, wa, wb, wide, bound);
      // f on [u, 1] of the window, from u = 0: each interval found free of roots is split off
      // it, so a step is one de Casteljau pass; each such pass adds its rounding to the band.
      zs_Real rest[zs_N], right[zs_N];
      zs_toBernstein(wide, rest, c);
      zs_Real maxAbs = zs_maxAbs(rest), noise = rtNoise(bound, maxAbs);
      zs_Real passNoise = zs_EPS * zs_Real(4 * zs_DEGREE) * maxAbs;
      float tolerance = rt.tangentTolerance / len;  // in units of s
      bool mayZoom = windows + 1 < RT_MAX_WINDOWS && len > 4.0 * rt.tangentTolerance;
      bool zoom = false;
      // F undefined on the whole ray, or an empty segment (a ray that misses the domain or is
      // cut away by a clip plane): nothing to find. Such a lane still runs the isolation body
      // once, on coefficients of no meaning, so `none` holds for it there: a root "found" in
      // them would be refined on a window of negative length, whose stop test never passes.
      done = !defined || !(len > 0.0);
      u = 0.0;
      // The whole window's control points are loose: it is decided at once too rarely to be
      // worth a step, so the walk starts with its halves.
      size = 0.5;
      int node = 0;  // [u, u + size] is the node-th interval of its size: u = node * size
      zs_Real lambda = zs_Real(size);  // where [u, u + size] ends in the rest [u, 1]
      // Isolation: the first interval of the tree, left to right, that holds a root. The body
      // is kept to what every step needs (llvmpipe runs all of it for every group of pixels);
      // what the interval found needs is computed after the loop.
      do {
        float w = u + size;
        zs_split(rest, lambda, b, right);
        // The next interval after one with no root starts at w and is as large as the highest
        // tree node starting there: 2^(trailing zeros of its index) times this one. Its lambda
        // is computed here, beside the split, so no division waits for the classification.
        int index = node + 1, up = index & -index;
        float climbed = size * float(up);
        zs_Real climbedLambda = w < 1.0 ? zs_Real(climbed) / zs_Real(1.0 - w) : zs_Real(1.0);
        // (all beyond the noise on one side: its sign; all within it; V; V of the derivative)
        ivec4 k = zs_bands(b, noise);
        // Signs the rounding cannot have changed.
        bool startPos = b[0] > noise, startNeg = b[0] < -noise;
        bool endPos = b[zs_DEGREE] > noise, endNeg = b[zs_DEGREE] < -noise;
        bool none = done || k.x != 0;
        bool monotone = k.w == 0;
        // Monotone with both ends of one sign: no root, and no touching either (the least |f|
        // is at an end, which the neighbouring interval holds).
        none = none || (monotone && ((startPos && endPos) || (startNeg && endNeg)));
        // Ends of opposite signs hold a root; one sign change of the control polygon, or a
        // monotone f, makes it the only one.
        isolated = !none && ((startPos && endNeg) || (startNeg && endPos)) &&
                   (k.z == 1 || monotone);
        bool undecided = !none && !isolated;
        // Every coefficient within the noise: this expansion cannot tell f from 0 here, and
        // halving cannot change that; an expansion about this interval (never the whole
        // window: the walk starts with its halves) alone can (5.).
        bool blurred = k.y == 1;
        bool small = size <= tolerance;
        zoom = undecided && (small || blurred) && mayZoom;
        found = isolated || (undecided && small && !zoom);  // a hit (header, 4.)
        // Next: the left half of an undecided interval; after one with no root, the climbed one.
        lambda = none ? climbedLambda : 0.5 * lambda;
        node = none ? index >> ((floatBitsToInt(float(up)) >> 23) - 127) : 2 * node;
        zs_take(rest, right, none);
        noise += none ? passNoise : zs_Real(0.0);
        u = none ? w : u;
        size = (found || zoom) ? size : (none ? climbed : 0.5 * size);
      } while (!(done || found || zoom || u >= 1.0) && ++step < RT_MAX_STEPS);
      // Next window: the undecided interval; after a window with no root, the rest of the
      // segment, expanded anew (shorter than the window before, so its noise is smaller). Out
      // of steps, the segment ends without a hit.
      bool more = !done && (zoom || (!found && u >= 1.0 && wb < tb));
      done = !more;
      if (more) {
        float next = wa + (u + size) * len;
        wa = zoom ? wa + u * len : wb;
        wb = zoom ? next : tb;
      }
    }
  } while (!done && ++windows < RT_MAX_WINDOWS);
  isolated = isolated && found;
  float lo = u, hi = u + size, flo = float(b[0]);  // bracket of the root found, and f(lo)
  float stop = rt.epsilon / (16.0 * len);
  // An isolated root starts its refinement where the control polygon crosses 0; an
  // undecidable interval's hit is its middle.
  float x = isolated ? u + size * zs_firstCrossing(b) : u + 0.5 * size;

  // Refinement of an isolated root: Halley steps safeguarded by bisection inside the
  // bracket, on the power basis (Horner, far cheaper than a de Casteljau pass), until a step
  // is below stop. Its own loop: a Horner step is a fraction of an isolation step, and a
  // shared loop body would pay for both on every iteration.
  bool refining = isolated;
  do {
    if (refining) {  // the body runs once even for lanes with nothing to refine
      vec3 f = zs_powerAt(c, zs_Real(2.0 * x - 1.0));  // in s' = 2s - 1
      float slope = 2.0 * f.y, curve = 8.0 * f.z;  // df/ds, d2f/ds2
      if ((f.x > 0.0) == (flo > 0.0) && f.x != 0.0) { lo = x; flo = f.x; } else { hi = x; }
      // Halley's step: cubic convergence where Newton's is quadratic, for one more Horner row.
      float dx = 2.0 * f.x * slope / (2.0 * slope * slope - f.x * curve);
      float next = x - dx;
      // A step below stop has converged, even where it rounds onto the bracket's end
      // (the bracket test alone would then bisect on and on).
      bool converged = f.x == 0.0 || abs(dx) <= stop;
      if (!(next > lo && next < hi)) next = converged ? clamp(next, lo, hi) : 0.5 * (lo + hi);
      converged = converged || abs(next - x) <= stop || hi - lo <= stop;
      x = f.x == 0.0 ? x : next;
      refining = refining && !converged;
    }
  } while (refining && ++step < RT_MAX_STEPS);
  tHit = wa + len * x;
  tAfter = wa + len * hi;
  return found;
}
