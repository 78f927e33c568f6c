// ---- raytrace_main.frag.glsl (render stage): follows the prelude, the generated formula
// block (zs_F, zs_FGrad) and, for the Bernstein method, the generated ray polynomial. Owns
// what the tracing methods share: the camera rays, the passes (the primary ray, a shadow
// ray per light with shading.shadows, one reflection ray), blending, the outputs. The method's file comes after this
// one and defines rtMarch(), which finds the hits of one ray (raytrace_shading.frag.glsl,
// between the two, defines shade()):
//   raytrace_sampling.frag.glsl   thesis Algorithm 1: sign samples + bisection per leaf
//   raytrace_bernstein.frag.glsl  exact root isolation of polynomials, octree front to back
//   raytrace_interval.frag.glsl   affine forms along the ray for every other formula; its
//                                 primary rays start where the beam pass left their tile
//                                 (raytrace_beam.frag.glsl, whose main() replaces this one's)
// docs/renderer.md explains the design; docs/camera.md the camera contract. No array is
// indexed by a run-time value: llvmpipe keeps constant-indexed arrays in registers but
// spills dynamically indexed ones to memory.

// The frame's parameters arrive as the flat varyings `rt` (frame_params.glsl, before this file).

layout(location = 0) out vec4 rtOutColor;
layout(location = 1) out float rtOutDepth;

// The program variant (render/ray_tracer.cpp defines these after #version): features that
// are off are absent, not masked. llvmpipe runs every branch and every loop at least once
// for each group of pixels, so a masked-off feature costs nearly as much as a used one.
#ifndef RT_SAMPLES
#define RT_SAMPLES 1     // N: N x N rays per pixel
#endif
#ifndef RT_MAX_HITS
#define RT_MAX_HITS 1    // hits kept per primary ray: 1 when opaque, tracing.hits otherwise
#endif
#ifndef RT_CLIP_PLANES
#define RT_CLIP_PLANES 0  // cutting clip planes, in rt.clip0 .. rt.clip3
#endif
#ifndef RT_REFLECTION
#define RT_REFLECTION 1  // one reflection ray off the first hit
#endif
#ifndef RT_COLOR
#define RT_COLOR 0       // the coloring (raytrace_shading.frag.glsl)
#endif
#ifndef RT_BEAM_TILE
#define RT_BEAM_TILE 8   // pixels per side of a beam pass tile (interval method)
#endif
#ifndef RT_KEY_LIGHT
#define RT_KEY_LIGHT (-rt.forward)  // towards the first directional light, else the eye
#endif

#if RT_COLOR == 1 || RT_COLOR == 2
// The curvature at the first hit of the pixel-center ray (NaN where nothing is hit): read
// back for the automatic color range and by the render tests (docs/curvature.md).
layout(location = 2) out float rtOutValue;
#endif

// The hits of the ray o + t d with t >= tStart inside the domain, nearest first, at most
// `wanted` (<= RT_MAX_HITS): their t and (grad F, F) there. Returns how many were found.
int rtMarch(vec3 o, vec3 d, float tStart, int wanted, out float hitT[RT_MAX_HITS],
            out vec4 hitG[RT_MAX_HITS]);

// Ray parameter interval inside the box [lo, hi]; empty when x > y.
vec2 slab(vec3 lo, vec3 hi, vec3 ro, vec3 inv) {
  vec3 a = (lo - ro) * inv, b = (hi - ro) * inv;
  vec3 n = min(a, b), f = max(a, b);
  return vec2(max(max(n.x, n.y), n.z), min(min(f.x, f.y), f.z));
}

// The ray's parameter interval inside the domain: its box, and its ball when the domain is a
// sphere (the box is then the ball's bounding box). Empty when x > y.
vec2 domainInterval(vec3 o, vec3 d, vec3 inv) {
  vec2 t = slab(rt.domainMin, rt.domainMax, o, inv);
  vec3 oc = o - rt.ball.xyz;
  float a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - rt.ball.w * rt.ball.w;
  float disc = b * b - a * c, root = sqrt(max(disc, 0.0));
  vec2 s = disc >= 0.0 ? vec2(-b - root, -b + root) / a : vec2(1.0, -1.0);
  return rt.ball.w > 0.0 ? vec2(max(t.x, s.x), min(t.y, s.y)) : t;
}

// The part of t where the ray keeps plane . (o + t d) <= plane.w (a clip plane).
vec2 rtClipPlane(vec4 plane, vec3 o, vec3 d, vec2 t) {
  float nd = dot(plane.xyz, d), room = plane.w - dot(plane.xyz, o);
  if (nd > 0.0) t.y = min(t.y, room / nd);
  else if (nd < 0.0) t.x = max(t.x, room / nd);
  else if (room < 0.0) t = vec2(1.0, -1.0);
  return t;
}

#if RT_CLIP_PLANES > 0
// How far p lies on the kept side of the nearest clip plane (unused slots are 1e30 away):
// the cut highlight, and whether a point is cut away (negative).
float rtCutDepth(vec3 p) {
  return min(min(rt.clip0.w - dot(rt.clip0.xyz, p), rt.clip1.w - dot(rt.clip1.xyz, p)),
             min(rt.clip2.w - dot(rt.clip2.xyz, p), rt.clip3.w - dot(rt.clip3.xyz, p)));
}
#endif

// The part of the ray inside the domain (box and ball) and on the kept side of every clip
// plane: what the volume mode integrates over. Empty when x > y.
vec2 rtDomainSpan(vec3 o, vec3 d, vec3 inv) {
  vec2 t = domainInterval(o, d, inv);
#if RT_CLIP_PLANES > 0
  t = rtClipPlane(rt.clip0, o, d, t);
#endif
#if RT_CLIP_PLANES > 1
  t = rtClipPlane(rt.clip1, o, d, t);
#endif
#if RT_CLIP_PLANES > 2
  t = rtClipPlane(rt.clip2, o, d, t);
#endif
#if RT_CLIP_PLANES > 3
  t = rtClipPlane(rt.clip3, o, d, t);
#endif
  return t;
}

// The part of the ray where hits can lie: the domain span inside the padded box of the
// hierarchy's leaves. Every march clips its rays with it; the beam pass encloses a tile's
// rays in the domain's and the leaves' box only, which can only start the walk earlier.
// Empty when x > y.
vec2 rtHitInterval(vec3 o, vec3 d, vec3 inv) {
  vec2 t = rtDomainSpan(o, d, inv);
  vec2 box = slab(rt.rootMin - rt.pad, rt.rootMax + rt.pad, o, inv);
  return vec2(max(t.x, box.x), min(t.y, box.y));
}

// How far p lies inside the domain's boundary (negative outside): the border highlight.
float domainDepth(vec3 p) {
  vec3 m = min(p - rt.domainMin, rt.domainMax - p);
  return rt.ball.w > 0.0 ? rt.ball.w - length(p - rt.ball.xyz) : min(min(m.x, m.y), m.z);
}

// 1 / d without infinities: a zero component becomes 1e30 (the slab test stays finite).
vec3 safeInverse(vec3 d) { return 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0))); }

// lights.space = "camera": a light's direction and position given in camera coordinates
// (from the eye, x right, y up, z towards the viewer) moved into the world with the frame's
// camera; RT_LIGHTS, RT_SHADOW_RAYS and RT_KEY_LIGHT call these (render/shading_defines.cpp).
vec3 rtCameraVector(vec3 v) { return v.x * rt.right + v.y * rt.up - v.z * rt.forward; }
vec3 rtCameraPoint(vec3 v) { return rt.eye + rtCameraVector(v); }

#ifdef RT_VOLUME
vec3 rtVolume(vec3 o, vec3 d, out float through);  // raytrace_volume.frag.glsl
#endif

// The color of a hit at p with (grad F, F) = g seen along rd: raytrace_shading.frag.glsl.
// Curvature colorings leave the curvature there in rtShadeValue. With shading.shadows, bit i
// of rtShadowMask set means that light i does not reach the hit being shaded.
vec3 shade(vec3 p, vec4 g, vec3 rd);
float rtShadeValue = 0.0;
uint rtShadowMask = 0u;

#ifdef RT_SHADOWS
// The shadow ray of light k from p: its direction d, and how far along it the light is.
// RT_SHADOW_RAYS (render/shading_defines.cpp) has one entry per light, compared with k
// (constants, no array indexed at run time).
#define RT_SHADOW_DIRECTIONAL(i, towards) if (k == (i)) { d = towards; reach = 1e30; }
#define RT_SHADOW_POINT(i, position) if (k == (i)) { vec3 v = (position) - p; reach = length(v); d = v / max(reach, 1e-30); }
void rtShadowRay(int k, vec3 p, out vec3 d, out float reach) {
  d = vec3(0.0, 0.0, 1.0);
  reach = 0.0;
  RT_SHADOW_RAYS
}
#endif

// The ray through image point q, in pixels from the top-left corner of the full image
// (docs/camera.md): its origin ro and unit direction rd.
void cameraRay(vec2 q, out vec3 ro, out vec3 rd) {
  vec2 uv = vec2((2.0 * q.x / rt.resolution.x - 1.0) * rt.resolution.x / rt.resolution.y,
                 1.0 - 2.0 * q.y / rt.resolution.y) * rt.planeHalf;
  ro = (rt.ortho != 0) ? rt.eye + uv.x * rt.right + uv.y * rt.up : rt.eye;
  rd = (rt.ortho != 0) ? rt.forward : normalize(rt.forward + uv.x * rt.right + uv.y * rt.up);
}

// The interval method's hints for a ray's walk (raytrace_interval.frag.glsl): the length of its
// first segment, how much longer each segment after one without root is, and (set by
// rtFirstRoot) the width of the segment that isolated the last root.
float rtFirstSegment = 1e30, rtGrowth = 1.5, rtIsolatedWidth = 0.0;

#ifdef RT_HAS_BEAM
// The beam pass's result for this pixel's tile (raytrace_beam.frag.glsl): no ray of the tile
// has a root before x, and y is the length of the segment there that the beam could not
// clear. rtBeamOn is 0 when no beam pass ran for this picture (the curvature probe).
uniform sampler2D rtBeam;
uniform int rtBeamOn;
#endif

// The beam pass and its tile mask have their own main (raytrace_beam.frag.glsl).
#if !defined(RT_BEAM) && !defined(RT_TILE_MASK)
void main() {
  RT_FRAME_BEGIN  // GLSL ES: the frame's uniforms into `rt` (shader_assembly.cpp)
  // Pixel (i, j) from the top-left of the full image (docs/camera.md).
  vec2 fragment = gl_FragCoord.xy + rt.pixelOrigin;
  vec2 pixel = vec2(fragment.x - 0.5, rt.resolution.y - fragment.y - 0.5);
#ifdef RT_VOLUME
  {  // F's field instead of its zero set: one ray through the pixel's center, no hits
    vec3 ro, rd;
    cameraRay(pixel + 0.5, ro, rd);
    float through;
    vec3 volume = rtVolume(ro, rd, through);
    rtOutColor = vec4(volume + through * rt.background, 1.0);
    rtOutDepth = uintBitsToFloat(0x7F800000u);
#if RT_COLOR == 1 || RT_COLOR == 2
    rtOutValue = uintBitsToFloat(0x7FC00000u);
#endif
    return;
  }
#endif
  const int n = RT_SAMPLES, grid = n * n;
  // Depth comes from the pixel-center ray; an even N x N grid has none, so one more ray
  // (depth only) is traced there.
  const int rays = grid + (n % 2 == 0 ? 1 : 0), centerRay = n % 2 == 0 ? grid : grid / 2;
  // Passes per ray: the primary ray; with shading.shadows one shadow ray per light from its
  // first hit (which is shaded after them); one reflection ray.
#ifdef RT_SHADOWS
  const int shadowPasses = RT_SHADOWS;
#define RT_PASSES (1 + RT_SHADOWS + RT_REFLECTION)
#else
  const int shadowPasses = 0;
#define RT_PASSES (1 + RT_REFLECTION)
#endif
  const int reflectionPass = RT_REFLECTION != 0 ? 1 + shadowPasses : -1;
  const int passes = RT_PASSES;
  float alpha = clamp(rt.opacity, 0.0, 1.0), w = RT_REFLECTION != 0 ? rt.primaryWeight : 1.0;
  float depth = uintBitsToFloat(0x7F800000u);  // +inf: no hit
  float value = uintBitsToFloat(0x7FC00000u);  // NaN: no hit
  vec3 sum = vec3(0.0);

  // Where the primary rays' walk starts, and the length of its first segment. A single ray
  // can decide longer segments than the whole tile's beam could: 8 times the beam's last
  // took the fewest steps (4 and 16 more, on the gyroid, Schwarz P, metaballs, bumpy sphere).
  float beamStart = 0.0, beamSegment = 1e30;
#ifdef RT_HAS_BEAM
  if (rtBeamOn != 0) {
    vec2 beam = texelFetch(rtBeam, ivec2(gl_FragCoord.xy) / RT_BEAM_TILE, 0).xy;
    beamStart = beam.x;
    beamSegment = 8.0 * beam.y;
  }
#endif

  // do-while, not for: llvmpipe tests a loop's exit only at the end of its body, so a for
  // loop runs its (large) body once more, masked off, after its last real iteration.
  int s = 0;
  do {
    vec2 offset = s < grid ? (vec2(s % n, s / n) + 0.5) / float(n) - 0.5 : vec2(0.0);
    vec3 ro, rd;
    cameraRay(pixel + offset + 0.5, ro, rd);
    bool colorRay = s < grid;
    vec3 color = vec3(0.0);
    float firstT = -1.0;
    vec4 firstG = vec4(0.0);

    // Pass 0: the primary ray, its hits blended front to back with the opacity (the first
    // hit weighted w when reflecting). Passes 1 .. shadowPasses: a shadow ray from the first
    // hit towards each light; the primary hits are shaded after the last of them. Then one
    // opaque reflection ray off the first hit, weighted alpha * (1 - w). One loop, so
    // rtMarch and its calls of F are inlined once.
    int pass = 0;
    float firstW = 0.0;  // the width of the segment that isolated the first hit
#ifdef RT_SHADOWS
    // The primary ray's hits, kept for shading after the shadow rays.
    int keptFound = 0;
    float keptT[RT_MAX_HITS];
    vec4 keptG[RT_MAX_HITS];
    rtShadowMask = 0u;
#endif
#if RT_PASSES > 1
    do {
#else
    // One pass is a block, not a loop: NVIDIA's compiler (driver 580) dropped the whole body
    // of this do-while when its trip count was the constant 1 (no hit anywhere).
    {
#endif
      vec3 o = ro, d = rd;
      float tStart = beamStart, passAlpha = alpha, passScale = 1.0;
      rtFirstSegment = beamSegment;
      rtGrowth = 1.5;
      int wanted = RT_MAX_HITS;
      int shaded = pass;  // whose hits this pass shades: 0 the primary ray's, -1 none
      if (pass >= 1) {  // a shadow or reflection ray, from the first hit
        o = ro + firstT * rd;
        tStart = max(4.0 * rt.epsilon, 1e-4 * length(rt.domainMax - rt.domainMin));  // leave the surface
        wanted = 1;
        rtFirstSegment = firstW;
        // It mostly leaves the surface through empty space: segments twice as long each time
        // take fewer steps there; primary rays, which mostly approach the surface, grow by 1.5.
        rtGrowth = 2.0;
      }
#ifdef RT_SHADOWS
      float reach = 0.0;  // a shadow ray: the distance to its light
      if (pass >= 1 && pass <= shadowPasses) rtShadowRay(pass - 1, o, d, reach);
#endif
      if (pass == reflectionPass) {
        vec3 nrm = length(firstG.xyz) > 0.0 ? normalize(firstG.xyz) : -rd;
        d = reflect(rd, dot(nrm, rd) < 0.0 ? nrm : -nrm);
        passAlpha = 1.0; passScale = alpha * (1.0 - w);
      }
      float hitT[RT_MAX_HITS];
      vec4 hitG[RT_MAX_HITS];
      int found = rtMarch(o, d, tStart, wanted, hitT, hitG);
      if (pass == 0 && found > 0) { firstT = hitT[0]; firstG = hitG[0]; }
      if (pass == 0) firstW = rtIsolatedWidth;
#ifdef RT_SHADOWS
      if (pass == 0 && found > 0 && colorRay) {  // shaded once the shadow rays are in
        keptFound = found; keptT = hitT; keptG = hitG;
        shaded = -1;
      }
      if (pass >= 1 && pass <= shadowPasses) {
        if (found > 0 && hitT[0] < reach) rtShadowMask |= 1u << uint(pass - 1);
        shaded = pass == shadowPasses ? 0 : -1;
        o = ro; d = rd; found = keptFound; hitT = keptT; hitG = keptG;
      }
      if (pass == reflectionPass) rtShadowMask = 0u;  // its hit is lit by every light
#endif

      float transmit = 1.0;
      if (shaded >= 0) {
#if RT_MAX_HITS == 1
      // One hit at most: shade it unconditionally (a loop would run its body twice).
      vec3 lit = shade(o + hitT[0] * d, hitG[0], d);
      if (shaded == 0 && s == centerRay) value = rtShadeValue;
      if (found > 0 && colorRay) {
        color += passScale * passAlpha * ((shaded == 0) ? w : 1.0) * lit;
        transmit = 1.0 - passAlpha;
      }
#else
      // Shade the kept hits front to back, outside the march: shade() is long and every
      // loop body runs at least once, so it runs max(found, 1) times per pass, not per step.
      for (int j = 0; j < found && colorRay; ++j) {
        float tj = 0.0;
        vec4 gj = vec4(0.0);
        for (int m = 0; m < RT_MAX_HITS; ++m) {
          if (m == j) { tj = hitT[m]; gj = hitG[m]; }
        }
        float share = (shaded == 0 && j == 0) ? w : 1.0;
#ifdef RT_SHADOWS
        if (j > 0) rtShadowMask = 0u;  // shadows fall on the first hit
#endif
        color += passScale * transmit * passAlpha * share * shade(o + tj * d, gj, d);
        if (shaded == 0 && j == 0 && s == centerRay) value = rtShadeValue;
        transmit *= 1.0 - passAlpha;
      }
#endif
      color += passScale * transmit * rt.background;  // what the kept hits let through
      }
#if RT_PASSES > 1
    } while (++pass < passes && colorRay && firstT >= 0.0);
#else
    }
#endif
#ifdef RT_MARKERS
    // highlights.singular: the certified singular points as small spheres, drawn where they
    // are nearer than the surface (a constant loop: unrolled, constant indices).
    float tMark = firstT >= 0.0 ? firstT : uintBitsToFloat(0x7F800000u);
    vec3 nMark = vec3(0.0);
    bool marked = false;
    for (int k = 0; k < RT_MARKER_COUNT; ++k) {
      vec3 oc = ro - rtMarkers[k].xyz;
      float b = dot(oc, rd), c = dot(oc, oc) - rtMarkers[k].w * rtMarkers[k].w;
      float disc = b * b - c * dot(rd, rd), tm = (-b - sqrt(max(disc, 0.0))) / dot(rd, rd);
      bool hit = disc >= 0.0 && tm > 0.0 && tm < tMark;
#if RT_CLIP_PLANES > 0
      hit = hit && rtCutDepth(rtMarkers[k].xyz) >= 0.0;  // a marker cut away is not drawn
#endif
      tMark = hit ? tm : tMark;
      nMark = hit ? (ro + tm * rd - rtMarkers[k].xyz) / rtMarkers[k].w : nMark;
      marked = marked || hit;
    }
    if (marked) {
      color = rtMarkerColor * (0.35 + 0.65 * max(dot(nMark, RT_KEY_LIGHT), 0.0));
      firstT = tMark;
    }
#endif
    if (s == centerRay && firstT >= 0.0) depth = firstT;
    if (colorRay) sum += color;
  } while (++s < rays);
  rtOutColor = vec4(sum / float(grid), 1.0);
  rtOutDepth = depth;
#if RT_COLOR == 1 || RT_COLOR == 2
  rtOutValue = depth < uintBitsToFloat(0x7F800000u) ? value : uintBitsToFloat(0x7FC00000u);
#endif
}
#endif  // !RT_BEAM && !RT_TILE_MASK
