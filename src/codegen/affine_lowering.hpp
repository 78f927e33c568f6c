#pragma once
// Affine lowering: takes the expression graph and the root of F, puts out the straight-line
// program of affine rules that encloses F and dF/dt along a ray segment, one step per value.
// Both readers of the interval method's formula take it from here, so they apply the same
// rules in the same order: the interval GLSL emitter writes it as text (emit_interval_glsl.hpp),
// the tape interpreter (src/interpreter) encodes it as data.
//
// Value i is the result of steps[i]. The rule choices:
//   - leaves: the coordinates as affine forms of tau, constants rounded outward to floats,
//     parameters as points, the ray direction's components as exact constants;
//   - a product with a float constant or a direction component is a scaling, a product with a
//     factor constant along the ray has no tau^2 term (mulk);
//   - sin and cos of one operand share one evaluation (a SinCos step and its Partner);
//   - polynomial rules (neg, add, sub, mul, square) leave their rounding unsettled: `depth`
//     counts the longest chain of them, and a Settle step adds it once, before any other rule
//     reads the form and at the end.
#include <cstdint>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

struct AffineStep {
  enum class Kind : std::uint8_t {
    Coordinate,      // x, y or z along the segment: axis = ival (0, 1, 2)
    Constant,        // [lo, hi] (lo == hi: a float); nan: undefined wherever it is used
    Param,           // zs_params[ival] as a point
    Direction,       // the ray direction's component ival, exact
    Rule,            // op's rule on values a (and b), ival = PowI's exponent
    Scale,           // value a times the float `lo`
    ScaleDirection,  // value a times the direction's component ival
    MulK,            // value a times value b, b constant along the ray
    SinCos,          // sin and cos of value a: this step is op's (Sin or Cos), the next the other's
    Partner,         // the other half of the SinCos before it
    Settle,          // value a with its unsettled rounding added (depth = ival)
  };
  Kind kind = Kind::Rule;
  Op op = Op::Const;
  std::int32_t a = -1, b = -1;
  std::int32_t ival = 0;
  float lo = 0, hi = 0;
  bool nan = false;
  // Part of dF/dt only (F does not need it): its domain errors go to the derivative's flag.
  bool derivativeOnly = false;
};

struct AffineProgram {
  std::vector<AffineStep> steps;
  std::int32_t f = -1, df = -1;  // the settled values of F and dF/dt
  // steps[0, fEnd) compute F; later ones only dF/dt (the point where F's partial flag is read).
  std::int32_t fEnd = 0;
};

// f must be a node of g; the derivative along the ray is derived here (g is not changed).
AffineProgram lowerAffine(const Graph& g, NodeId f);

}  // namespace zs
