// ---- raytrace_shading.frag.glsl (render stage): the color of one hit, shade(), called by
// raytrace_main.frag.glsl. Phong lighting with the scene's lights and the front or back
// material, or a curvature / normal coloring, then the highlights. docs/renderer.md has the
// lighting formula, docs/curvature.md the curvature.
//
// The program variant (render/shading_defines.cpp puts these after #version):
//   RT_LIGHTS     one RT_DIRECTIONAL(towards, color) or RT_POINT(position, color) per light
//                 that is on, with constant arguments (color = color * intensity): the
//                 lights are compile-time constants, unrolled, so they cost no flat varyings
//                 (llvmpipe has about 128 components for all of them) and no uniform reads.
//   RT_KEY_LIGHT  unit vector towards the first directional light (the singular markers).
//   RT_COLOR      0 material, 1 Gaussian curvature, 2 mean curvature, 3 normal; a
//                 curvature coloring leaves its value in rtShadeValue (raytrace_main's).
//   RT_SURFACES   several surfaces (codegen's surfaces block): each hit is shaded with
//                 the normal and material of the surface it lies on; RT_INTERSECTION
//                 marks where two of them meet.
//   RT_SHADOWS    shading.shadows: the entries are RT_DIRECTIONAL_SHADOWED(i, ...) and
//                 RT_POINT_SHADOWED(i, ...), light i adding nothing where bit i of
//                 rtShadowMask (raytrace_main's shadow rays) is set.
#ifndef RT_LIGHTS
#define RT_LIGHTS
#endif

// dot(reflect(-L, n), -rd)^shininess without forming the reflected vector; 0 for a light
// behind the surface.
float phongSpecular(vec3 n, vec3 L, float nl, vec3 rd, float shininess) {
  float r = max(dot(L, rd) - 2.0 * nl * dot(n, rd), 0.0);
  return nl > 0.0 ? pow(r, shininess) : 0.0;
}

// One light's diffuse and specular terms, added up in shade(); `towards` is the unit
// vector to the light. Called with constant light arguments: inlined and folded.
void rtAddLight(vec3 n, vec3 rd, float shininess, vec3 towards, vec3 light, inout vec3 diffuse,
                inout vec3 specular) {
  float nl = dot(n, towards);
  diffuse += light * max(nl, 0.0);
  specular += light * phongSpecular(n, towards, nl, rd, shininess);
}
// The entries of RT_LIGHTS (GLSL 3.30 has no line continuation: one line each). A point
// light costs one normalization per hit; a directional light's vector is a constant.
#define RT_DIRECTIONAL(towards, light) rtAddLight(n, rd, phong.w, towards, light, diffuse, specular);
#define RT_POINT(position, light) rtAddLight(n, rd, phong.w, normalize((position) - p), light, diffuse, specular);
#define RT_DIRECTIONAL_SHADOWED(i, towards, light) if ((rtShadowMask & (1u << (i))) == 0u) { RT_DIRECTIONAL(towards, light) }
#define RT_POINT_SHADOWED(i, position, light) if ((rtShadowMask & (1u << (i))) == 0u) { RT_POINT(position, light) }

#if RT_COLOR == 1 || RT_COLOR == 2
mat3 zs_FHess(vec3 p);  // generated (codegen/emit_hessian.cpp) only for these colorings

// Curvature of the level set F = 0 at p with gradient g, oriented by grad F
// (docs/curvature.md): Gaussian K = g.adj(H).g / |g|^4, mean H = (|g|^2 tr H - g.H.g) / (2|g|^3).
float rtCurvature(vec3 p, vec3 g) {
  mat3 h = zs_FHess(p);
  float g2 = max(dot(g, g), 1e-30);
#if RT_COLOR == 1
  // Rows of the adjugate of a symmetric matrix: cross products of its columns.
  vec3 adjG = vec3(dot(cross(h[1], h[2]), g), dot(cross(h[2], h[0]), g), dot(cross(h[0], h[1]), g));
  return dot(g, adjG) / (g2 * g2);
#else
  float trace = h[0][0] + h[1][1] + h[2][2];
  return (g2 * trace - dot(g, h * g)) / (2.0 * g2 * sqrt(g2));
#endif
}

// Diverging map: blue for -range, white for 0, red for +range (clamped beyond).
vec3 rtDiverging(float v) {
  float t = clamp(v / rt.curvatureRange, -1.0, 1.0);
  vec3 white = vec3(0.96), blue = vec3(0.15, 0.3, 0.85), red = vec3(0.8, 0.1, 0.1);
  return t < 0.0 ? mix(white, blue, -t) : mix(white, red, t);
}
#endif

vec3 shade(vec3 p, vec4 g, vec3 rd) {
#ifdef RT_SURFACES
  // Several surfaces are traced as the product of their functions, whose gradient at a hit
  // is the hit surface's times the other factors: the surface p lies on gives the normal,
  // its side and the material instead (zs_surfaceAt, generated with the formula).
  vec4 product = g;
  int surface;
  float other;
  g = zs_surfaceAt(p, surface, other);
#endif
  float g2 = dot(g.xyz, g.xyz);
  float inv = g2 > 0.0 ? inversesqrt(g2) : 0.0;
  float cosine = dot(g.xyz, rd) * inv;
  bool front = cosine < 0.0;
  vec3 n = g2 > 0.0 ? g.xyz * (front ? inv : -inv) : -rd;
  vec4 phong = front ? rt.frontPhong : rt.backPhong;  // (ambient, diffuse, specular, shininess)
  vec3 base = front ? rt.frontColor : rt.backColor;
#ifdef RT_SURFACES
  if (surface > 0) {
    phong = front ? zs_surfaceFrontPhong[surface - 1] : zs_surfaceBackPhong[surface - 1];
    base = front ? zs_surfaceFrontColor[surface - 1] : zs_surfaceBackColor[surface - 1];
  }
#endif
  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
  RT_LIGHTS
#if RT_COLOR == 1 || RT_COLOR == 2
#ifdef RT_SURFACES
  // The product's zero set has the hit surface's curvature, oriented by the product's
  // gradient: the mean curvature turns sign where the other factors are negative.
  rtShadeValue = rtCurvature(p, product.xyz);
#if RT_COLOR == 2
  if (dot(product.xyz, g.xyz) < 0.0) rtShadeValue = -rtShadeValue;
#endif
#else
  rtShadeValue = rtCurvature(p, g.xyz);
#endif
  base = rtDiverging(rtShadeValue);
#endif
  vec3 color = base * (phong.x + phong.y * diffuse) + phong.z * specular;
#if RT_COLOR == 3
  color = n * 0.5 + 0.5;
#endif
#ifdef RT_CONTOURS
  // shading.contours: g = k * spacing within width / 2 measured along the surface, i.e. the
  // distance to the level over the slope of g within the tangent plane.
  vec4 level = zs_contour(p);
  float slope = length(level.xyz - dot(level.xyz, n) * n);
  float k = level.w / rt.contourSpacing;
  if (abs(k - floor(k + 0.5)) * rt.contourSpacing < 0.5 * rt.contourWidth * slope)
    color = rt.contourColor;  // false for NaN: no line where g is undefined
#endif
#ifdef RT_INTERSECTION
  // Where another surface passes within the tolerance, measured to first order.
  if (other < zs_intersectionTolerance) color = zs_intersectionColor;
#endif
  if ((rt.silhouetteOn != 0) && abs(cosine) < rt.silhouetteThreshold) color = rt.silhouetteColor;
  if ((rt.borderOn != 0) && domainDepth(p) < rt.borderThreshold) color = rt.borderColor;
#if RT_CLIP_PLANES > 0
  if ((rt.cutOn != 0) && rtCutDepth(p) < rt.cutThreshold) color = rt.cutColor;
#endif
  return clamp(color, 0.0, 1.0);
}
