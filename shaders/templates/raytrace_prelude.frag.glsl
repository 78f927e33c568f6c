#version 330 core
// zeroset fragment shader, its first piece: the prelude (owned by src/codegen; the contract
// and the list of every piece are in docs/codegen.md). The next piece, the formula block, is
// generated from the formula and defines zs_F and zs_FGrad; raytrace_main.frag.glsl, later,
// traces rays and calls them through the prototypes below. Everything here is named zs_*,
// the formula block uses zs_* and t<N>.

// F at p, or zs_UNDEFINED where p lies outside F's domain (sqrt of a negative number, ...).
// Defined values are clamped to [-zs_HUGE, zs_HUGE], so they never reach the sentinel.
float zs_F(vec3 p);
// xyz = gradient of F at p, w = F at p (exactly what zs_F returns). Where F is undefined:
// (0, 0, 0, zs_UNDEFINED); where only the gradient is undefined: (0, 0, 0, F).
vec4 zs_FGrad(vec3 p);

const float zs_UNDEFINED = 3.0e38;
const float zs_HUGE = 1.0e38;
// Stands in for +-infinity inside the formula: GLSL does not require infinities.
const float zs_FLT_MAX = 3.4028235e38;

// The ray tracer must not count a sign change between a defined and an undefined sample:
// the boundary of F's domain is not part of the surface.
bool zs_isUndefined(float f) { return f >= zs_UNDEFINED; }

// Several surfaces whose product stands in 1 for a surface's F where F is undefined
// (scene/surfaces.cpp): bit i set where the last zs_F or zs_FGrad took stand-in i. The
// product jumps where a stand-in starts or ends, which the sampling method must not take for
// a root. Always 0 for one surface.
uint zs_standIns = 0u;

// ---- results --------------------------------------------------------------------------
// u: some operation F needs was outside its domain. NaN can still arise from inf - inf or
// 0 * inf after an overflow; it is reported as undefined too.
float zs_finishF(float f, bool u) {
  return (u || isnan(f)) ? zs_UNDEFINED : clamp(f, -zs_HUGE, zs_HUGE);
}

vec4 zs_finishFGrad(vec3 g, float f, bool u, bool ug) {
  if (u || isnan(f)) return vec4(0.0, 0.0, 0.0, zs_UNDEFINED);
  float fc = clamp(f, -zs_HUGE, zs_HUGE);
  if (ug || any(isnan(g))) return vec4(0.0, 0.0, 0.0, fc);
  return vec4(clamp(g, -zs_HUGE, zs_HUGE), fc);
}

// ---- operations GLSL leaves undefined somewhere -------------------------------------------
// Each sets u where the double-precision semantics (expr/tape.hpp, applyScalar) give NaN
// and returns a finite placeholder there, so later operations stay well defined.

// a / 0 is +-infinity with the sign of a (the sign of a zero divisor is not reliable on
// GPUs); 0 / 0 is undefined.
float zs_div(float a, float b, inout bool u) {
  u = u || (b == 0.0 && a == 0.0);
  return b != 0.0 ? a / b : (a < 0.0 ? -zs_FLT_MAX : zs_FLT_MAX);
}

float zs_sqrt(float a, inout bool u) {
  u = u || a < 0.0;
  return sqrt(max(a, 0.0));
}

// log(0) = -infinity.
float zs_log(float a, inout bool u) {
  u = u || a < 0.0;
  return a > 0.0 ? log(a) : -zs_FLT_MAX;
}

// asin and acos through atan: llvmpipe's own are off by up to 4e-4 near +-1 (found by
// tests/render/interval_rules_test.cpp), its atan by less than 1e-6; (1 - a)(1 + a) keeps
// 1 - a^2 accurate there.
float zs_asinOf(float a) {
  float c = clamp(a, -1.0, 1.0);
  return atan(c, sqrt((1.0 - c) * (1.0 + c)));
}
float zs_acosOf(float a) {
  float c = clamp(a, -1.0, 1.0);
  return atan(sqrt((1.0 - c) * (1.0 + c)), c);
}

float zs_asin(float a, inout bool u) {
  u = u || abs(a) > 1.0;
  return zs_asinOf(a);
}

float zs_acos(float a, inout bool u) {
  u = u || abs(a) > 1.0;
  return zs_acosOf(a);
}

// a^b as C's pow: GLSL pow is only defined for a > 0. 0^b is 0 (b > 0), 1 (b = 0) or
// infinity (b < 0); a negative base needs an integral exponent, its sign follows parity.
float zs_pow(float a, float b, inout bool u) {
  if (a > 0.0) return pow(a, b);
  if (a == 0.0) return b > 0.0 ? 0.0 : (b == 0.0 ? 1.0 : zs_FLT_MAX);
  bool integral = floor(b) == b;
  u = u || !integral;
  float m = pow(-a, b);
  return (integral && mod(b, 2.0) == 1.0) ? -m : m;
}

// ---- operations without a (safe) GLSL built-in ----------------------------------------
// atan(y, x) is undefined at (0, 0) in GLSL; C's atan2 gives 0 there.
float zs_atan2(float y, float x) { return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x); }

float zs_cbrt(float a) { return a == 0.0 ? 0.0 : sign(a) * pow(abs(a), 1.0 / 3.0); }

// tanh = (e^2a - 1) / (e^2a + 1) overflows to inf / inf in some drivers; |a| >= 10 is
// already +-1 in float.
float zs_tanh(float a) { return tanh(clamp(a, -10.0, 10.0)); }
