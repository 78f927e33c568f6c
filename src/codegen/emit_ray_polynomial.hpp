#pragma once
// The ray polynomial of a polynomial formula: takes the graph and the root of F, puts out
// GLSL that computes, for a ray segment p + s v (s in [-1, 1]: p is the segment's midpoint,
// v half of it), the coefficients of the univariate polynomial f(s) = F(p + s v), plus the
// Bernstein kernels of that degree (on [0, 1], the same segment) which
// raytrace_bernstein.frag.glsl isolates roots with:
//
//   const int zs_DEGREE = D;  const int zs_N = D + 1;
//   #define zs_Real float (double from kDoubleDegree on)
//   #define zs_Wide double (vec2, a double-float, in GLSL ES), zs_Bound double (float)
//   const zs_Bound zs_ROUNDINGS;  // roundings on the longest path to a Bernstein coefficient
//   bool zs_FPolyOn(vec3 o, vec3 d, float wa, float wb, out zs_Wide c[zs_N], out zs_Bound
//        bound);  // c[k] of s^k on the segment [wa, wb] of the ray o + t d; bound: the
//        expansion with every operation on absolute values
//   void zs_toBernstein(zs_Wide c[zs_N], out zs_Real b[zs_N], out zs_Real narrow[zs_N]);
//        // Bernstein on [0, 1] (s' = (s+1)/2) in zs_Wide, rounded once; narrow: c rounded once
//   void zs_split(zs_Real b[zs_N], zs_Real lambda, out zs_Real left[zs_N],
//        out zs_Real right[zs_N]);  // f on [0, lambda] and [lambda, 1]: one de Casteljau pass
//   void zs_take(inout zs_Real b[zs_N], zs_Real next[zs_N], bool take);  // b = next if take
//   vec3 zs_powerAt(zs_Real c[zs_N], zs_Real x);  // (f, f', f''/2) at s = x in [-1, 1], Horner
//   float zs_firstCrossing(zs_Real b[zs_N]);  // first zero of the control polygon, in [0, 1]
//   zs_Real zs_maxAbs(zs_Real b[zs_N]);       // largest |coefficient|
//   ivec4 zs_bands(zs_Real b[zs_N], zs_Real noise);  // (every b_i beyond noise: its sign, else
//        0; every b_i within it; sign changes of b; of its differences)
//   void zs_extremes(zs_Real b[zs_N], out zs_Real lo, out zs_Real hi);  // min and max of b
//   vec2 zs_clearEnds(zs_Real b[zs_N], zs_Real lim);  // fractions at each end where |f| > band
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

// zs_FPoly (the Taylor expansion) and the conversion to Bernstein coefficients always run in
// double (GL_ARB_gpu_shader_fp64), with an a priori bound of their rounding. From this
// degree on the isolation (de Casteljau, classification, Horner) runs in double too: below
// it, float isolation with re-expansion where its noise band cannot decide is faster; from
// it, float's band (relative to the segment's largest coefficient, which grows like the
// segment's length to the power D) makes so many rays re-expand that double is faster, and
// it keeps far sheets of degree-12 surfaces in place (docs/renderer.md).
inline constexpr int kDoubleDegree = 7;

struct RayPolynomialGlsl {
  std::string source;  // the block, ending with a newline
  int degree = 0;      // D
  bool fp64 = true;    // the expansion runs in double (GL_ARB_gpu_shader_fp64), else double-float
  bool doublePrecision = false;  // fp64 and D >= kDoubleDegree: the isolation runs in double too
};

// GLSL ES 3.00 (WebGL2) has no double: there the expansion runs in double-float arithmetic
// (a value is a float pair, about 44 bits) with the same a priori bound taken with its
// roundoff, and the isolation in float, up to this degree. Above it the web build traces
// with interval arithmetic (docs/web.md).
inline constexpr int kWebBernsteinMaxDegree = 12;
// A software WebGL's JIT (SwiftShader's) takes time that grows faster than the expansion's
// length: written out term by term, a double-float expansion of more than this many
// products (the Sarti dodecic's has about 1,400) compiled for minutes. Such an expansion
// writes its convolutions of at least `terms` terms as calls of one loop (zs_dfConvolve),
// which sums the same products in ascending order; the rest stay written out, since a loop
// over arrays runs several times slower.
struct DoubleFloatLoops {
  int products = 600;  // loops only in an expansion of more products than this written out
  int terms = 40;
};

// Degree of f(s) the block would have: the structural degree of F, or nothing when F is not
// a polynomial in x, y, z (parameters are coefficients).
std::optional<int> rayPolynomialDegree(const Graph& g, NodeId f);

// Nothing when F is not a polynomial. The formula block (emit_glsl.hpp) must precede it: it
// declares zs_params.
// fp64 false (GLSL ES): the expansion in double-float and the isolation in float, whatever
// the degree, its long convolutions as `loops` says.
std::optional<RayPolynomialGlsl> emitRayPolynomialGlsl(const Graph& g, NodeId f, bool fp64 = true,
                                                       DoubleFloatLoops loops = {});

// The Bernstein kernels alone for degree d (part of the block above); exposed for tests.
std::string emitBernsteinKernelsGlsl(int d, bool doublePrecision = false, bool fp64 = true);

}  // namespace zs
