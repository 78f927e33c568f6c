// ---- raytrace_volume.frag.glsl (render stage): render.mode = "volume". F's scalar field
// (zs_F, which is F - level) drawn by emission and absorption along the ray through its span
// in the domain (rtDomainSpan: box, ball and clip planes; not only where the surface is, as
// for hits): at each sample
// v = zs_F(p) has the color of the diverging map of v / range and the extinction
// density * exp(-(v / falloff)^2). `steps` samples, one at the middle of each step (the
// midpoint rule), composited front to back; docs/renderer.md, "Volume rendering", has the
// step error. Joined after raytrace_shading.frag.glsl; compiled only where RT_VOLUME is
// defined (ProgramVariant::volume).

#ifdef RT_VOLUME
// Blue for -1, white for 0, red for +1 (clamped beyond): the curvature colorings' map.
vec3 rtVolumeColor(float x) {
  float t = clamp(x, -1.0, 1.0);
  vec3 white = vec3(0.96), blue = vec3(0.15, 0.3, 0.85), red = vec3(0.8, 0.1, 0.1);
  return t < 0.0 ? mix(white, blue, -t) : mix(white, red, t);
}

// The ray's color over the background; `through` is how much of the background shows.
vec3 rtVolume(vec3 o, vec3 d, out float through) {
  vec2 span = rtDomainSpan(o, d, safeInverse(d));
  float t0 = max(span.x, 0.0);
  through = 1.0;
  vec3 color = vec3(0.0);
  if (!(span.y > t0)) return color;
  int steps = max(rt.volumeSteps, 1);
  float h = (span.y - t0) / float(steps);
  int i = 0;
  do {
    vec3 p = o + (t0 + (float(i) + 0.5) * h) * d;
    float v = zs_F(p);
    if (!isnan(v) && !isinf(v)) {
      float u = v / rt.volumeFalloff;
      float alpha = 1.0 - exp(-rt.volumeDensity * exp(-u * u) * h);
      color += through * alpha * rtVolumeColor(v / rt.volumeRange);
      through *= 1.0 - alpha;
    }
  } while (++i < steps && through > 1e-4);
  return color;
}
#endif
