// ---- interval_prelude.frag.glsl (codegen stage): interval arithmetic for the interval
// method (tracing.method = "interval"). Joined after raytrace_prelude.frag.glsl, before
// affine_prelude.frag.glsl, whose zsa_* rules fall back on these (one zsi_* rule per
// opcode, src/codegen/op_interval_glsl.cpp) for the operations without a first-order rule.
// The rules mirror the CPU's (src/interval): an interval is a vec2 (lo, hi); an operand that
// lies partly outside an operation's domain is restricted to it (zsi_partial records that it
// happened), one wholly outside sets the flag u (F is defined nowhere there).
//
// Rounding (docs/codegen.md, "Interval GLSL"): GLSL has no directed rounding, so every
// result is widened outward after it is computed: arithmetic by ZSI_REL of its magnitude,
// the built-in functions by ZSI_FN_REL and ZSI_FN_ABS (plus a share of the argument for
// sin, cos, tan and exp, whose argument reduction loses accuracy as it grows). The render
// tests compare the method with double precision on the GPU that runs them
// (tests/render/interval_method_test.cpp).

#define ZSI_INF uintBitsToFloat(0x7F800000u)
const float ZSI_REL = 2.384185791015625e-7;  // 2^-22: 4x the error of one rounded operation
const float ZSI_TINY = 1.17549435e-38;       // FLT_MIN: results flushed to zero
const float ZSI_FN_REL = 1.9073486328125e-6; // 2^-19
const float ZSI_FN_ABS = 1.9073486328125e-6; // 2^-19
const float ZSI_ARG = 4.76837158203125e-7;   // 2^-21 of |argument|: argument reduction
const float ZSI_PI = 3.14159265;

// Operations that restricted an operand to their domain, or divided by an interval holding
// 0: F may be undefined or unbounded somewhere on the segment, so no monotonicity proof.
bool zsi_partial = false;

// Outward by `rel` of the magnitude and `abs` (one multiply-add and one add per end). An
// infinite end stays infinite, except a lower end of +inf (an overflow on both ends), which
// becomes NaN and then unbounded (zsi_unNaN): only looser.
vec2 zsi_widen(vec2 r, float rel, float abs_) {
  return r + vec2(-1.0, 1.0) * (abs(r) * rel + abs_);
}
vec2 zsi_out(vec2 r) { return zsi_widen(r, ZSI_REL, ZSI_TINY); }
vec2 zsi_outFn(vec2 r, float arg) {
  return zsi_widen(r, ZSI_FN_REL, ZSI_FN_ABS + ZSI_ARG * arg);
}
// inf - inf and 0 * inf give NaN: an endpoint that is NaN becomes unbounded.
vec2 zsi_unNaN(vec2 r) { return vec2(isnan(r.x) ? -ZSI_INF : r.x, isnan(r.y) ? ZSI_INF : r.y); }
float zsi_mag(vec2 a) { return max(abs(a.x), abs(a.y)); }

vec2 zsi_point(float v) { return zsi_out(vec2(v)); }
vec2 zsi_neg(vec2 a) { return -a.yx; }
vec2 zsi_add(vec2 a, vec2 b) { return zsi_unNaN(zsi_out(a + b)); }
vec2 zsi_sub(vec2 a, vec2 b) { return zsi_unNaN(zsi_out(a - b.yx)); }

vec2 zsi_mul(vec2 a, vec2 b) {
  vec4 c = a.xxyy * b.xyxy;
  c = mix(c, vec4(0.0), isnan(c));  // a corner 0 * inf: the products around it are 0
  return zsi_out(vec2(min(min(c.x, c.y), min(c.z, c.w)), max(max(c.x, c.y), max(c.z, c.w))));
}

vec2 zsi_div(vec2 a, vec2 b) {
  if (b.x <= 0.0 && b.y >= 0.0) { zsi_partial = true; return vec2(-ZSI_INF, ZSI_INF); }
  vec4 c = a.xxyy / b.xyxy;  // inf / inf corners are NaN; the others reach their limits
  vec4 l = mix(c, vec4(ZSI_INF), isnan(c)), h = mix(c, vec4(-ZSI_INF), isnan(c));
  return zsi_out(vec2(min(min(l.x, l.y), min(l.z, l.w)), max(max(h.x, h.y), max(h.z, h.w))));
}

// x^k for x >= 0 by binary powering; k is a constant at every call, so it unrolls.
float zsi_ipow(float x, int k) {
  float r = 1.0, base = x;
  for (int n = k; n > 0; n >>= 1) {
    if ((n & 1) != 0) r *= base;
    base *= base;
  }
  return r;
}

// Even powers depend on |x| only, so [-1, 2]^2 = [0, 4]; k - 1 roundings per endpoint.
vec2 zsi_powi(vec2 a, int k) {
  int m = abs(k);
  vec2 p;
  if (m % 2 == 0) {
    float lo = (a.x <= 0.0 && a.y >= 0.0) ? 0.0 : min(abs(a.x), abs(a.y));
    p = vec2(zsi_ipow(lo, m), zsi_ipow(zsi_mag(a), m));
  } else {
    p = vec2(sign(a.x) * zsi_ipow(abs(a.x), m), sign(a.y) * zsi_ipow(abs(a.y), m));
  }
  p = zsi_widen(p, ZSI_REL * float(m), ZSI_TINY);
  if (k >= 0) return k == 0 ? vec2(1.0) : p;
  return zsi_div(vec2(1.0), p);
}

vec2 zsi_sqrt(vec2 a, inout bool u) {
  u = u || a.y < 0.0;
  zsi_partial = zsi_partial || a.x < 0.0;
  vec2 r = zsi_outFn(sqrt(max(a, 0.0)), 0.0);
  return vec2(max(r.x, 0.0), r.y);
}

float zsi_logOf(float v) { return v > 0.0 ? log(v) : -ZSI_INF; }
vec2 zsi_log(vec2 a, inout bool u) {
  u = u || a.y < 0.0;
  zsi_partial = zsi_partial || a.x <= 0.0;
  return zsi_outFn(vec2(zsi_logOf(a.x), zsi_logOf(a.y)), 0.0);
}

vec2 zsi_exp(vec2 a) {
  vec2 r = exp(a);
  r = zsi_widen(r, ZSI_FN_REL + ZSI_ARG * zsi_mag(a), ZSI_TINY);
  return vec2(max(r.x, 0.0), r.y);
}


// sin and cos by their Taylor form about the middle m with the Lagrange remainder:
// sin(m + h) = sin m + h cos m - h^2/2 sin(xi), so with |h| <= r the range lies in
// sin m +- (r |cos m| + r^2/2), and likewise for cos. One sin and one cos of m serve both
// rules (the compiler shares them when a formula has sin and cos of one argument), against
// two evaluations and two extremum tests for the endpoint rule; the result is exact at an
// extremum (cos m = 0) and loses only r^2/2 where the function is steep.
vec2 zsi_taylorTrig(float value, float slope, vec2 a, float m) {
  float r = max(a.y - m, m - a.x);  // covers the rounding of m
  float spread = r * abs(slope) + 0.5 * r * r;
  vec2 v = zsi_outFn(vec2(value - spread, value + spread), abs(m));
  return (r < ZSI_PI) ? clamp(v, -1.0, 1.0) : vec2(-1.0, 1.0);  // also infinite endpoints
}
vec2 zsi_sin(vec2 a) {
  float m = 0.5 * a.x + 0.5 * a.y;
  return zsi_taylorTrig(sin(m), cos(m), a, m);
}
vec2 zsi_cos(vec2 a) {
  float m = 0.5 * a.x + 0.5 * a.y;
  return zsi_taylorTrig(cos(m), sin(m), a, m);
}

// Could phase + k period (k integer) lie in [lo, hi]? Widened so that rounding can only
// answer a false "yes" (a looser result), never a false "no".
bool zsi_mayHit(vec2 a, float phase, float period) {
  float lo = (a.x - phase) / period, hi = (a.y - phase) / period;
  float slack = 1e-5 * (1.0 + max(abs(lo), abs(hi)));
  return floor(hi + slack) >= ceil(lo - slack);
}

vec2 zsi_tan(vec2 a) {
  if (!(a.y - a.x < ZSI_PI) || zsi_mayHit(a, 0.5 * ZSI_PI, ZSI_PI)) {
    zsi_partial = true;  // a pole: unbounded, not a surface
    return vec2(-ZSI_INF, ZSI_INF);
  }
  // Near a pole tan magnifies its argument's error by 1 + tan^2, and a GPU's tan (sin over
  // cos, each with an absolute error) is off by about that much there: widened by it.
  vec2 t = vec2(tan(a.x), tan(a.y));
  vec2 slope = 1.0 + t * t;
  float argErr = ZSI_FN_ABS + ZSI_ARG * zsi_mag(a);
  return zsi_unNaN(t + vec2(-1.0, 1.0) * (abs(t) * ZSI_FN_REL + argErr * slope));
}

vec2 zsi_asin(vec2 a, inout bool u) {
  u = u || a.x > 1.0 || a.y < -1.0;
  zsi_partial = zsi_partial || a.x < -1.0 || a.y > 1.0;
  vec2 r = zsi_outFn(vec2(zs_asinOf(a.x), zs_asinOf(a.y)), 0.0);
  return clamp(r, -0.5 * ZSI_PI - 1e-6, 0.5 * ZSI_PI + 1e-6);
}

vec2 zsi_acos(vec2 a, inout bool u) {
  u = u || a.x > 1.0 || a.y < -1.0;
  zsi_partial = zsi_partial || a.x < -1.0 || a.y > 1.0;
  vec2 r = zsi_outFn(vec2(zs_acosOf(a.y), zs_acosOf(a.x)), 0.0);
  return clamp(r, 0.0, ZSI_PI + 1e-6);
}

vec2 zsi_atan(vec2 a) {
  return clamp(zsi_outFn(atan(a), 0.0), -0.5 * ZSI_PI - 1e-6, 0.5 * ZSI_PI + 1e-6);
}

// atan2 jumps across the negative x axis and takes every angle next to the origin.
vec2 zsi_atan2(vec2 y, vec2 x) {
  if (y.x <= 0.0 && y.y >= 0.0 && x.x <= 0.0) return vec2(-ZSI_PI - 1e-6, ZSI_PI + 1e-6);
  vec4 c = vec4(zs_atan2(y.x, x.x), zs_atan2(y.x, x.y), zs_atan2(y.y, x.x), zs_atan2(y.y, x.y));
  return zsi_outFn(vec2(min(min(c.x, c.y), min(c.z, c.w)), max(max(c.x, c.y), max(c.z, c.w))), 0.0);
}

vec2 zsi_abs(vec2 a) {
  return a.x >= 0.0 ? a : (a.y <= 0.0 ? -a.yx : vec2(0.0, max(-a.x, a.y)));
}
// sinh and cosh overflow to infinity, which the widening keeps.
vec2 zsi_sinh(vec2 a) { return zsi_outFn(sinh(a), zsi_mag(a)); }
vec2 zsi_cosh(vec2 a) {
  vec2 m = zsi_abs(a);
  vec2 r = zsi_outFn(cosh(m), zsi_mag(a));
  return vec2(max(r.x, 1.0), r.y);
}
vec2 zsi_tanh(vec2 a) { return clamp(zsi_outFn(vec2(zs_tanh(a.x), zs_tanh(a.y)), 0.0), -1.0, 1.0); }
vec2 zsi_cbrt(vec2 a) { return zsi_outFn(vec2(zs_cbrt(a.x), zs_cbrt(a.y)), 0.0); }

vec2 zsi_sign(vec2 a) { return sign(a); }
vec2 zsi_floor(vec2 a) { return floor(a); }
vec2 zsi_ceil(vec2 a) { return ceil(a); }
vec2 zsi_min(vec2 a, vec2 b) { return min(a, b); }
vec2 zsi_max(vec2 a, vec2 b) { return max(a, b); }

// pow(u, v) at one corner of a box with u >= 0, as C defines the limits there.
float zsi_powCorner(float u, float v) {
  if (u > 0.0) return pow(u, v);
  return v > 0.0 ? 0.0 : (v == 0.0 ? 1.0 : ZSI_INF);
}
// Non-negative bases: monotone in each argument, so the extremes are at the corners.
vec2 zsi_powCorners(vec2 x, vec2 y) {
  float u0 = max(x.x, 0.0);
  vec4 c = vec4(zsi_powCorner(u0, y.x), zsi_powCorner(u0, y.y), zsi_powCorner(x.y, y.x),
                zsi_powCorner(x.y, y.y));
  // pow is exp2(v log2 u): its error grows with |v log2 u|.
  float spread = zsi_mag(y) * max(abs(log2(max(u0, 1e-30))), abs(log2(max(x.y, 1e-30))));
  vec2 r = zsi_widen(vec2(min(min(c.x, c.y), min(c.z, c.w)), max(max(c.x, c.y), max(c.z, c.w))),
                     ZSI_FN_REL + ZSI_ARG * spread, ZSI_TINY);
  return vec2(max(r.x, 0.0), r.y);
}
// Negative bases are outside the domain of a non-integer exponent, but C's pow defines them at
// integer exponents an exponent interval may hold: |pow(x, n)| = pow(|x|, n) bounds them.
vec2 zsi_pow(vec2 a, vec2 b, inout bool u) {
  bool integerInside = ceil(b.x) <= b.y;
  u = u || (a.y < 0.0 && !integerInside);
  zsi_partial = zsi_partial || a.x < 0.0;
  vec2 r = a.y >= 0.0 ? zsi_powCorners(a, b) : vec2(ZSI_INF, -ZSI_INF);
  if (a.x < 0.0 && integerInside) {
    vec2 m = zsi_powCorners(vec2(max(-a.y, 0.0), -a.x), b);
    r = vec2(min(r.x, -m.y), max(r.y, m.y));
  }
  return r;
}

