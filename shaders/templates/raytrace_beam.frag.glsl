// ---- raytrace_beam.frag.glsl (render stage): the beam pass of the interval method. Follows
// raytrace_interval.frag.glsl; its main() is compiled only with RT_BEAM defined (the beam
// program of render/ray_tracer.cpp) and then replaces raytrace_main's.
//
// Why: the rays of neighbouring pixels walk through the same empty space, and each used to
// prove it empty on its own (on the bumpy sphere about half of a primary ray's isolation
// steps). One fragment per tile of RT_BEAM_TILE x RT_BEAM_TILE pixels encloses all the tile's
// rays at once and walks them front to back as rtFirstRoot does, but only to prove segments
// empty: where it no longer can (its segment is as short as the beam is wide, or its step
// budget is spent) it stops and writes where that segment starts (x) and its length (y).
// Every primary ray of the tile starts its own walk there, with a first segment that long
// (raytrace_main.frag.glsl); no ray of the tile has a root sooner, so nothing is lost.
//
// The enclosure: the rays of a tile go through the tile's rectangle of the image. Their
// origins differ from the central ray's by at most rhoO and their unit directions by at most
// rhoD, both reached at a corner (the distance to the central origin is convex on the
// rectangle and the angle to the central direction quasi-convex, so both peak at a vertex).
// The point at parameter t of any of them therefore lies within rhoO + rhoD t of the central
// ray's point in each coordinate: zsa_lateral widens the coordinates' affine forms by that,
// and the forms of F then hold for the whole cross-section of the beam at each tau.
#ifdef RT_BEAM
const int RT_BEAM_STEPS = 48;  // the beam's step budget; it stops where it is (still exact)

void main() {
  RT_FRAME_BEGIN
  // The tile's rectangle in image points (pixels from the top-left of the full image); one
  // fragment per tile, counted bottom-up like gl_FragCoord.
  const float T = float(RT_BEAM_TILE);
  vec2 tile = floor(gl_FragCoord.xy) + rt.pixelOrigin / T;  // a band starts on a tile row
  vec2 corner = vec2(tile.x * T, rt.resolution.y - (tile.y + 1.0) * T);
  vec3 oc, dc;
  cameraRay(corner + 0.5 * T, oc, dc);
  float rhoO = 0.0, rhoD = 0.0;
  for (int k = 0; k < 4; ++k) {
    vec3 ok, dk;
    cameraRay(corner + T * vec2(float(k % 2), float(k / 2)), ok, dk);
    rhoO = max(rhoO, length(ok - oc));
    rhoD = max(rhoD, length(dk - dc));
  }
  // Rounding: each ray's own origin and direction are computed in float.
  rhoO = rhoO * (1.0 + 64.0 * ZSI_REL) + (length(oc) + rt.planeHalf) * (16.0 * ZSI_REL);
  rhoD = rhoD * (1.0 + 64.0 * ZSI_REL) + 16.0 * ZSI_REL;

  // The box where roots can lie (raytrace_first_roots.frag.glsl clips every ray to it): the
  // tile's rays, unit speed, meet it between tLo and tHi.
  vec3 lo = max(rt.domainMin, rt.rootMin - rt.pad), hi = min(rt.domainMax, rt.rootMax + rt.pad);
  float tLo = max(length(max(max(lo - oc, oc - hi), 0.0)) - rhoO, 0.0);
  float tHi = length(max(abs(oc - lo), abs(oc - hi))) + rhoO;

  float u = tLo, size = tHi - tLo;  // the segment [u, u + size] being classified
  float start = tLo, segment = size;
  bool done = !(size > 0.0), clear = false;
  int step = 0;
  do {
    if (!done) {  // as in rtFirstRoot: a lane that is done must not run the body again
      float t0 = u, t1 = min(u + size, tHi);
      float tm = 0.5 * t0 + 0.5 * t1, h = rtHalfWidth(t0, t1, tm);
      zsa_lateral = rhoO + rhoD * max(t1, 0.0);  // the beam is widest at its far end
      vec3 F;
      vec2 D;
      bool partial;
      zs_FAffine(oc, dc, tm, h, F, D, partial);
      vec2 range = zsa_range(F);
      bool none = !(range.x <= 0.0 && range.y >= 0.0);  // also F defined nowhere
      // Roots lie only where |c + s tau| <= r (rtZeroWindow): the segment before that window
      // is clear too (pulled back by a further 1e-4 of tau).
      float cut = t0;
      if (!none && F.y != 0.0) {
        float first = rtZeroWindow(F, h, abs(tm) + h).x - 1e-4;
        cut = first > -1.0 ? clamp(tm + h * first, t0, t1) : t0;
      }
      // Shorter than the beam is wide, a segment no longer gets tighter: stop there.
      float width = 2.0 * (rhoO + rhoD * max(cut, 0.0));
      bool stuck = !none && (t1 - cut <= width || step + 1 >= RT_BEAM_STEPS);
      start = stuck ? cut : start;
      segment = stuck ? t1 - cut : segment;
      // Next: after a clear segment the one to its right, 1.5 times as long; else the left
      // half of what is left after the cut.
      u = none ? t1 : cut;
      size = none ? 1.5 * (t1 - t0) : 0.5 * (t1 - cut);
      clear = none && t1 >= tHi;
      done = stuck || clear;
    }
  } while (!done && ++step < RT_BEAM_STEPS);
  if (!done) {  // out of steps right after a clear segment: stop where the next one starts
    start = u;
    segment = size;
  }
  // No ray of the tile has a root in the box: the largest float, so each ray's walk is empty.
  start = clear ? 3.4028235e38 : start;
  rtOutColor = vec4(start, segment, 0.0, 1.0);  // the beam target's one (RG32F) attachment
}
#endif  // RT_BEAM

#ifdef RT_TILE_MASK
// Tile skipping (render/ray_tracer.cpp, markClearTiles) draws the tiles that the beam found
// clear with this program, color writes off, to mark them in the stencil buffer; the main
// pass then starts no fragment there.
void main() { rtOutColor = vec4(0.0); }
#endif  // RT_TILE_MASK
