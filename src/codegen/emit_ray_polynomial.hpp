#pragma once
// The ray polynomial of a polynomial formula: takes the graph and the root of F, puts out
// GLSL that computes, for a ray segment p + s v (s in [-1, 1]: p is the segment's midpoint,
// v half of it), the coefficients of the univariate polynomial f(s) = F(p + s v), plus the
// Bernstein kernels of that degree (on [0, 1], the same segment) which
// raytrace_bernstein.frag.glsl isolates roots with:
//
//   const int zs_DEGREE = D;  const int zs_N = D + 1;
//   #define zs_Real float (double from kDoubleDegree on), zs_Real3 vec3 (dvec3)
//   bool zs_FPoly(zs_Real3 p, zs_Real3 v, out zs_Real c[zs_N]);  // power basis, c[k] of s^k
//   void zs_toBernstein(zs_Real c[zs_N], out float b[zs_N]); // Bernstein on [0, 1], s' = (s+1)/2
//   void zs_restrict(float b[zs_N], float u, float w, out float r[zs_N]);  // to [u, w]
//   vec3 zs_powerAt(zs_Real c[zs_N], zs_Real x);  // (f, f', f''/2) at s = x in [-1, 1], Horner
//   float zs_firstCrossing(float b[zs_N]);    // first zero of the control polygon, in [0, 1]
//   float zs_maxAbs(float b[zs_N]);           // largest |coefficient|
//   vec4 zs_classify(float b[zs_N]);  // (min, max, sign changes of b, of its derivative)
//
// zs_FPoly is truncated Taylor arithmetic: every node carries the coefficients of its own
// polynomial in s, up to its structural degree (expr/degree.hpp) and at most D, so products
// are convolutions with constant indices and nothing is ever dropped that could survive to
// F. Subexpressions free of x, y, z (parameters, sqrt(5), ...) are plain scalars. Every loop
// over coefficients is unrolled here because D is known: the shader indexes no array with a
// run-time value (llvmpipe would spill it to memory).
#include <optional>
#include <string>

#include "expr/graph.hpp"

namespace zs {

// From this degree on, zs_FPoly and the conversion to Bernstein coefficients run in double
// (GL_ARB_gpu_shader_fp64): a polynomial typed in the power basis cancels ever larger terms
// along a ray as its degree grows, and in float that noise hid sheets and moved roots of
// degree-12 surfaces (tests/render/degree_limit_test.cpp, docs/renderer.md). Isolation and
// its de Casteljau steps stay in float, on coefficients rounded once.
inline constexpr int kDoubleDegree = 9;

struct RayPolynomialGlsl {
  std::string source;  // the block, ending with a newline
  int degree = 0;      // D
  bool doublePrecision = false;  // D >= kDoubleDegree: the block needs GL_ARB_gpu_shader_fp64
};

// Degree of f(s) the block would have: the structural degree of F, or nothing when F is not
// a polynomial in x, y, z (parameters are coefficients).
std::optional<int> rayPolynomialDegree(const Graph& g, NodeId f);

// Nothing when F is not a polynomial. The formula block (emit_glsl.hpp) must precede it: it
// declares zs_params.
std::optional<RayPolynomialGlsl> emitRayPolynomialGlsl(const Graph& g, NodeId f);

// The Bernstein kernels alone for degree d (part of the block above); exposed for tests.
std::string emitBernsteinKernelsGlsl(int d, bool doublePrecision = false);

}  // namespace zs
