#pragma once
// Interval GLSL for a formula: takes the expression graph and the root of F, puts out the
// block the interval method (tracing.method = "interval") joins after the formula block:
//
//   void zs_FAffine(vec3 o, vec3 d, float tm, float h, out vec3 F, out vec2 D, out bool partial)
//
// Every non-leaf node becomes one `vec4 aN = zsa_<rule>(operands);`, an affine form along
// the ray segment (shaders/templates/affine_prelude.frag.glsl), or its interval rule on the
// operands' ranges where it has no first-order one (op_interval_glsl.hpp,
// shaders/templates/interval_prelude.frag.glsl); constants are rounded outward to floats.
// Chains of polynomial operations are settled (their rounding added to r) once, before any
// other rule reads them and at the end: `vec4 sN = zsa_settle(aN, k)`.
// F = vec3(c, s, r) holds F(o + t d) in c + s tau +- r for t = tm + h tau, tau in [-1, 1]
// (r = -1 where F is defined nowhere on the segment); D encloses the derivative along d,
// grad F . d (derived in forward mode along d, expr/derivative.hpp), over the segment
// (whole where it cannot be bounded); `partial` is true where some operation of F was
// restricted to its domain or divided by an interval holding 0 (F may be undefined or
// unbounded on part of the segment). docs/codegen.md ("Interval GLSL") states the contract.
#include <string>

#include "expr/graph.hpp"

namespace zs {

struct IntervalGlsl {
  std::string source;  // the interval block, ending with a newline
};

// f must be a node of g; the derivative along the ray is derived here (g is not changed).
IntervalGlsl emitIntervalGlsl(const Graph& g, NodeId f);

}  // namespace zs
