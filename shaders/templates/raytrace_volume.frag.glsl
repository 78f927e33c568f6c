// ---- raytrace_volume.frag.glsl (render stage): render.mode = "volume". F's scalar field
// (zs_F, which is F - level) drawn by emission and absorption along the ray through its span
// in the domain (rtDomainSpan: box, ball and clip planes; not only where the surface is, as
// for hits): at each sample
// v = zs_F(p) has the color of the diverging map of v / range and the extinction
// density * exp(-(v / falloff)^2). `steps` samples, one at the middle of each step (the
// midpoint rule), composited front to back; docs/renderer.md, "Volume rendering", has the
// step error. The last piece of every program: it skips stretches far from the level with
// what the interval method's pieces (zs_FAffine, rtHalfWidth) or the Bernstein method's
// (zs_FPolyOn, zs_clearEnds, rtNoise) define before it; compiled only where RT_VOLUME is
// defined (ProgramVariant::volume).

#ifdef RT_VOLUME
// Blue for -1, white for 0, red for +1 (clamped beyond): the curvature colorings' map.
vec3 rtVolumeColor(float x) {
  float t = clamp(x, -1.0, 1.0);
  vec3 white = vec3(0.96), blue = vec3(0.15, 0.3, 0.85), red = vec3(0.8, 0.1, 0.1);
  return t < 0.0 ? mix(white, blue, -t) : mix(white, red, t);
}

// A step whose midpoint's value of F lies at least this many falloffs from the level has an
// extinction below density * exp(-16): it is skipped (docs/renderer.md, "Volume rendering",
// has the error).
const float RT_VOLUME_CLEAR = 4.0;
// The ray is walked in runs of RT_VOLUME_RUN steps, and a run whose window is wider than
// RT_VOLUME_PART steps in parts that long, each with its own window. Every pixel walks the
// same runs and parts: on llvmpipe neighbouring pixels run in lock step, and a walk whose
// runs grow and shrink per pixel (tried) costs what its slowest pixel costs.
// Parts are shorter where the window comes from the ray polynomial's control points, whose
// expansion costs less than an affine form and whose windows are tighter.
#if defined(zs_Real) && !defined(RT_HAS_BEAM)
const int RT_VOLUME_RUN = 256, RT_VOLUME_PART = 32;
#else
const int RT_VOLUME_RUN = 256, RT_VOLUME_PART = 64;
#endif

// The steps [first, last) of the n steps of length h from ta whose midpoints may lie in the
// band |F| < band; first = last = n where none. The pipeline draws a volume with the
// interval method's program (RT_HAS_BEAM) or, for a polynomial, the Bernstein method's;
// the sampling program, which tests use as the reference, samples every step.
#ifdef RT_HAS_BEAM
// The interval method's program: by the affine form over the n steps, where
// |c + s tau| < r + band.
ivec2 rtVolumeWindow(vec3 o, vec3 d, float ta, float h, int n, float band) {
  float tb = ta + float(n) * h, tm = 0.5 * ta + 0.5 * tb, hw = rtHalfWidth(ta, tb, tm);
  vec3 F;
  vec2 D;
  bool partial;
  zs_FAffine(o, d, tm, hw, F, D, partial);
  vec2 range = zsa_range(F);  // empty where F is defined nowhere: nothing to draw either
  if (!(range.x < band && range.y > -band)) return ivec2(n);
  float reach = F.z + band;
  if (!(F.y != 0.0) || isinf(reach)) return ivec2(0, n);
  // tau where c + s tau = -reach and = +reach, as step positions k (midpoint k + 1/2), one
  // step wider on each side for the rounding of tau <-> t <-> k.
  vec2 tau = (vec2(-reach, reach) - F.x) / F.y;
  vec2 k = (tm + hw * vec2(min(tau.x, tau.y), max(tau.x, tau.y)) - ta) / h - 0.5;
  return ivec2(clamp(floor(k.x - 0.0625), 0.0, float(n)), clamp(floor(k.y + 0.0625) + 1.0, 0.0, float(n)));
}
#elif defined(zs_Real)
// The Bernstein method's program (a polynomial F; zs_Real comes with its ray polynomial
// block): f on the n steps, expanded about their middle, in the Bernstein basis. Where the
// control points stay beyond band + noise there is nothing; else the stretch at each end
// that the supporting line of the control points there keeps beyond the band is skipped
// (zs_clearEnds), with 1/16 of a step of slack for the rounding of t <-> k.
ivec2 rtVolumeWindow(vec3 o, vec3 d, float ta, float h, int n, float band) {
  zs_Wide wide[zs_N];
  zs_Bound bound;
  zs_Real b[zs_N], c[zs_N];
  if (!zs_FPolyOn(o, d, ta, ta + float(n) * h, wide, bound)) return ivec2(0, n);
  zs_toBernstein(wide, b, c);
  zs_Real lim = zs_Real(band) + rtNoise(bound, zs_maxAbs(b));
  zs_Real lo, hi;
  zs_extremes(b, lo, hi);
  // Overflow (an infinite or NaN coefficient or band) bounds nothing: every step is sampled.
  const zs_Real huge = zs_Real(3.0e38);
  if (!(abs(lo) < huge && abs(hi) < huge && lim < huge)) return ivec2(0, n);
  if (!(lo < lim && hi > -lim)) return ivec2(n);
  vec2 clear = zs_clearEnds(b, lim);
  // Step j's midpoint lies at (j + 1/2) / n of the stretch.
  float first = ceil(clear.x * float(n) - 0.5 - 0.0625);
  float last = floor((1.0 - clear.y) * float(n) - 0.5 + 0.0625) + 1.0;
  return first < last ? ivec2(clamp(first, 0.0, float(n)), clamp(last, 0.0, float(n))) : ivec2(n);
}
#else
// The sampling program: every step.
ivec2 rtVolumeWindow(vec3 o, vec3 d, float ta, float h, int n, float band) { return ivec2(0, n); }
#endif

// Composites the samples of steps [from, to) (from < to) of length h from t0 over color.
void rtVolumeSamples(vec3 o, vec3 d, float t0, float h, int from, int to, inout vec3 color,
                     inout float through) {
  int k = from;
  do {
    vec3 p = o + (t0 + (float(k) + 0.5) * h) * d;
    float v = zs_F(p);
    if (!isnan(v) && !isinf(v)) {
      float u = v / rt.volumeFalloff;
      float alpha = 1.0 - exp(-rt.volumeDensity * exp(-u * u) * h);
      color += through * alpha * rtVolumeColor(v / rt.volumeRange);
      through *= 1.0 - alpha;
    }
  } while (++k < to);
}

// The ray's color over the background; `through` is how much of the background shows.
// Only the steps in the windows of rtVolumeWindow are sampled; the others are skipped.
vec3 rtVolume(vec3 o, vec3 d, out float through) {
  vec2 span = rtDomainSpan(o, d, safeInverse(d));
  float t0 = max(span.x, 0.0);
  through = 1.0;
  vec3 color = vec3(0.0);
  if (!(span.y > t0)) return color;
  int steps = max(rt.volumeSteps, 1);
  float h = (span.y - t0) / float(steps);
  float band = RT_VOLUME_CLEAR * rt.volumeFalloff;
  int i = 0;
  do {
    int n = min(RT_VOLUME_RUN, steps - i);
    ivec2 w = rtVolumeWindow(o, d, t0 + float(i) * h, h, n, band);
    if (w.y - w.x > RT_VOLUME_PART) {
      int j = w.x - w.x % RT_VOLUME_PART;
      do {
        int m = min(RT_VOLUME_PART, n - j);
        ivec2 p = rtVolumeWindow(o, d, t0 + float(i + j) * h, h, m, band);
        if (p.x < p.y) rtVolumeSamples(o, d, t0, h, i + j + p.x, i + j + p.y, color, through);
        j += RT_VOLUME_PART;
      } while (j < w.y);
    } else if (w.x < w.y) {
      rtVolumeSamples(o, d, t0, h, i + w.x, i + w.y, color, through);
    }
    i += n;
  } while (i < steps && through > 1e-4);
  return color;
}
#endif
