// ---- affine_prelude.frag.glsl (codegen stage): first-order enclosures along the ray for the
// interval method (tracing.method = "interval"). Joined after interval_prelude.frag.glsl, whose
// zsi_* rules it falls back on, before the generated interval block, whose zs_FAffine calls
// one zsa_* rule per opcode (src/codegen/op_interval_glsl.cpp).
//
// Why: the natural interval extension forgets that x, y and z move together along a ray, so
// sin x cos y over a segment is as wide as over the segment's whole box and rays split far
// down. Here every quantity is a function of tau in [-1, 1], where the segment is
// t = tm + h tau, enclosed by an affine form vec4(c, s, r, m): each of its values at tau lies in
// c + s tau +- r (reduced affine arithmetic, Knoll et al. 2009; a Taylor model of order 1).
// The remainder r of a product or of sin of a short segment shrinks with the square of its
// length, so F's enclosure is tight enough to clip the segment to where c + s tau +- r can
// hold 0 (raytrace_interval.frag.glsl).
//
// Rounding (docs/codegen.md, "Interval GLSL"): a form is vec4(c, s, r, m), where m bounds
// |c| + |s| + r of the same operations done on absolute values, plus ZSI_ETA. The polynomial
// operations (neg, add, sub, scale, mul, sqr) are not widened one by one: each float
// operation errs by at most u |x| + FLT_MIN <= u m (u = 2^-24, FLT_MIN for results flushed
// to zero, hence ZSI_ETA = FLT_MIN / u in m), and errors that propagate through additions and
// products stay within u m per float operation on the path (the classical bound gamma_k m of
// a product-sum program, Higham, "Accuracy and Stability of Numerical Algorithms", ch. 3).
// So a chain of k such operations is exact to within k (2 ZSI_REL) m (2 ZSI_REL = 8u covers
// the at most 6 float operations deep of one affine product), and zsa_settle adds that to r
// once: the emitter settles a form before any other rule reads it and at the end (F and
// dF/dt), with k the longest chain since the last settling, which is far cheaper than
// widening every operation (docs/codegen.md). The other rules take settled
// operands and return settled results: r widened by ZSI_REL of the magnitudes that were
// rounded (twice that for the Taylor forms), plus FLT_MIN; function values and slopes carry
// the built-in functions' margins. An operation without a first-order rule, or whose
// operand's range leaves the function's domain, goes through its interval rule
// (zsa_fromInterval(zsi_*(zsa_range(a)))), which keeps the flags `u` and zsi_partial exactly
// as the interval block sets them. A NaN anywhere (overflow) makes the range the whole line:
// only looser.

const float ZSI_ETA = 1.9721523e-31;  // 2^-102 = FLT_MIN / 2^-24

// A settled result of a rule whose (c, s) were rounded from terms of size `magnitude`: r
// widened by rel of them (and of itself) and FLT_MIN, and m recomputed.
vec4 zsa_round(vec3 v, float magnitude, float rel) {
  float r = v.z + (magnitude + v.z) * rel + ZSI_TINY;
  return vec4(v.xy, r, magnitude + r + ZSI_ETA);
}

// The whole line: a form that holds every value.
vec4 zsa_whole() { return vec4(0.0, 0.0, ZSI_INF, ZSI_INF); }

// The form of a float interval (s = 0); unbounded ends give the whole line. Settled.
vec4 zsa_fromInterval(vec2 I) {
  if (!(I.x > -ZSI_INF && I.y < ZSI_INF)) return zsa_whole();
  float c = 0.5 * I.x + 0.5 * I.y, r = 0.5 * I.y - 0.5 * I.x;
  return zsa_round(vec3(c, 0.0, r), abs(c), ZSI_REL);
}
// An exact value (a constant that is a float, a component of the ray direction). Settled.
vec4 zsa_const(float v) { return vec4(v, 0.0, 0.0, abs(v) + ZSI_ETA); }

// Every value a settled form (or the tracer's (c, s, r)) takes on [-1, 1], outward; NaN
// ends are unbounded.
vec2 zsa_range(vec3 a) {
  float w = abs(a.y) + a.z;
  return zsi_unNaN(zsi_out(vec2(a.x - w, a.x + w)));
}
vec2 zsa_range(vec4 a) { return zsa_range(a.xyz); }

// How far the points enclosed may lie off the ray o + t d in each coordinate: 0 for one ray;
// the beam pass (raytrace_beam.frag.glsl) encloses all rays of a tile around its central one.
float zsa_lateral = 0.0;

// The coordinate o + d t on the segment; the slack also covers the point evaluations of the
// tracer at the segment's ends, which compute o + t d in float. Settled.
vec4 zsa_var(float o, float d, float tm, float h) {
  float c = o + d * tm, s = d * h;
  float r = (abs(o) + abs(d * tm) + abs(s)) * (2.0 * ZSI_REL) + ZSI_TINY + zsa_lateral;
  return vec4(c, s, r, abs(c) + abs(s) + r + ZSI_ETA);
}
// A parameter's value, widened by one rounding. Settled.
vec4 zsa_point(float v) { return zsa_round(vec3(v, 0.0, 0.0), abs(v), ZSI_REL); }

// The rounding of a chain of k polynomial operations, added to r once (header).
vec4 zsa_settle(vec4 a, float k) { return vec4(a.xy, a.z + (k * (2.0 * ZSI_REL)) * a.w, a.w); }

// The polynomial operations: unsettled (header).
vec4 zsa_neg(vec4 a) { return vec4(-a.xy, a.zw); }
vec4 zsa_add(vec4 a, vec4 b) { return a + b; }
vec4 zsa_sub(vec4 a, vec4 b) { return zsa_add(a, zsa_neg(b)); }
vec4 zsa_scale(vec4 a, float k) {
  if (k == 0.0) return vec4(0.0);  // 0 * inf is 0 here
  float ak = abs(k);
  return vec4(a.xy * k, a.z * ak, a.w * ak + ZSI_ETA);
}

// (ca + sa tau + ea)(cb + sb tau + eb): the tau^2 term sa sb tau^2 lies in sa sb (1/2 +- 1/2),
// so half of it moves into the center; the cross terms with the e's go into r. The terms of
// (c, s, r) on absolute values add up to ma mb exactly.
vec4 zsa_mul(vec4 a, vec4 b) {
  float ss = a.y * b.y, cc = a.x * b.x;
  float cs = a.x * b.y, sc = b.x * a.y;
  vec2 as = abs(a.xy), bs = abs(b.xy);
  float r = as.x * b.z + bs.x * a.z + 0.5 * abs(ss) + (as.y + a.z) * b.z + a.z * bs.y;
  return vec4(cc + 0.5 * ss, cs + sc, r, a.w * b.w + ZSI_ETA);
}
// a times k where k is constant along the ray (the emitter knows: it depends on no
// coordinate), so its slope is 0 and the product has no tau^2 term: two products for (c, s)
// instead of four. k's slope still enters r (as |k.y|), so the rule encloses for any k.
vec4 zsa_mulk(vec4 a, vec4 k) {
  float r = abs(k.x) * a.z + (k.z + abs(k.y)) * (abs(a.x) + abs(a.y) + a.z);
  return vec4(a.xy * k.x, r, a.w * k.w + ZSI_ETA);
}
// (c + s tau + e)^2 = c^2 + s^2/2 + 2 c s tau + s^2 (tau^2 - 1/2) + 2 (c + s tau) e + e^2.
vec4 zsa_sqr(vec4 a) {
  float ss = a.y * a.y, cc = a.x * a.x, cs = 2.0 * a.x * a.y;
  float r = 0.5 * ss + 2.0 * (abs(a.x) + abs(a.y)) * a.z + a.z * a.z;
  return vec4(cc + 0.5 * ss, cs, r, a.w * a.w + ZSI_ETA);
}

// A first-order result, or the interval rule's result over the same operand range where the
// form's remainder alone is wider than that whole range (a long segment's Taylor remainder can
// exceed the function's whole range). Not the narrower of the two ranges: on a nearly linear
// stretch the interval's range is narrower than the form's |s| + r by the curvature alone,
// and taking it threw the slope away (sqrt(x^2 + y^2 + z^2) along a ray lost its slope on
// every segment), and with it the tracer's clipping to the zero window and its growth
// prediction, which made the walk markedly slower.
vec4 zsa_tighter(vec4 A, vec2 I) {
  return (A.z <= (I.y - I.x)) ? A : zsa_fromInterval(I);
}

// f(x) for x = c + s tau + e with |s| + r <= R, from f(c) = v and f'(c) = p (each computed to
// within err) and the range q of f'' over c +- R: f(x) = f(c) + f'(c)(x - c) + f''(xi)/2 (x - c)^2
// with (x - c)^2 in [0, R^2] (Lagrange).
vec4 zsa_taylor(vec4 a, float R, float v, float p, float err, vec2 q) {
  float half2 = 0.5 * R * R * (1.0 + 4.0 * ZSI_REL);
  vec2 quad = half2 * vec2(min(q.x, 0.0), max(q.y, 0.0));
  float s = p * a.y;
  float r = (abs(p) + err) * a.z + err * (abs(a.y) + 1.0) + 0.5 * (quad.y - quad.x);
  vec3 t = vec3(v + 0.5 * (quad.x + quad.y), s, r);
  return zsa_round(t, abs(v) + abs(quad.x) + abs(quad.y) + abs(s), 2.0 * ZSI_REL);
}
float zsa_radius(vec4 a) { return (abs(a.y) + a.z) * (1.0 + ZSI_REL); }

// sin and cos of x = c + delta, delta = s tau + e in [-R, R], from v = f(c) and p = f'(c) (sin:
// v = sin c, p = cos c; cos: v = cos c, p = -sin c), by the addition theorem
// f(c + delta) = v cos delta + p sin delta:
//   v cos delta = v - v (1 - cos delta),          1 - cos delta in [0, k], k = min(R^2/2, 2);
//   p sin delta = p s tau + p e + p (sin delta - delta), |sin delta - delta| <= min(R^3/6, R + 1).
// The first term's range is centred (half of v k moves into the value). v and p are each
// off by at most err, which moves f by at most 2 err. This is tighter than the general Taylor
// form (zsa_taylor with f'' = -f over c +- R) and takes about half its operations. Where the
// remainder alone exceeds 1 (long segments), [-1, 1] itself (as in zsa_tighter).
vec4 zsa_trig(vec4 a, float R, float v, float p) {
  float err = ZSI_FN_REL + ZSI_FN_ABS + ZSI_ARG * abs(a.x);
  float R2 = R * R * (1.0 + 4.0 * ZSI_REL);
  float k = min(0.5 * R2, 2.0);
  float g = min(R2 * R * 0.16666667 * (1.0 + 4.0 * ZSI_REL), R + 1.0);  // 0.16666667 > 1/6
  float hv = 0.5 * k * v, s = p * a.y;
  float r = abs(hv) + abs(p) * (a.z + g) + 2.0 * err;
  vec4 A = zsa_round(vec3(v - hv, s, r), 2.0 * abs(v) + abs(s), 2.0 * ZSI_REL);
  return A.z <= 1.0 ? A : vec4(0.0, 0.0, 1.0, 1.0 + ZSI_ETA);
}
vec4 zsa_sin(vec4 a) { return zsa_trig(a, zsa_radius(a), sin(a.x), cos(a.x)); }
vec4 zsa_cos(vec4 a) { return zsa_trig(a, zsa_radius(a), cos(a.x), -sin(a.x)); }
// Both of one operand (the emitter pairs them): one sin and one cos of the center for the two.
void zsa_sincos(vec4 a, out vec4 s, out vec4 c) {
  float R = zsa_radius(a), sa = sin(a.x), ca = cos(a.x);
  s = zsa_trig(a, R, sa, ca);
  c = zsa_trig(a, R, ca, -sa);
}

// exp = exp' = exp'': the range of f'' is the interval rule's result, exp(c) / exp(R) to
// exp(c) exp(R), with the margins of three evaluations.
vec4 zsa_exp(vec4 a) {
  float R = zsa_radius(a), e = exp(a.x), eR = exp(R);
  float rel = ZSI_FN_REL + ZSI_ARG * abs(a.x);
  vec2 I = zsi_widen(vec2(e / eR, e * eR), 3.0 * rel + ZSI_ARG * R + 2.0 * ZSI_REL, ZSI_TINY);
  I = vec2(max(I.x, 0.0), I.y);
  return zsa_tighter(zsa_taylor(a, R, e, e, e * rel + ZSI_TINY, I), I);
}

// sqrt where the operand's range lies inside (0, inf); its interval rule (and flags)
// otherwise. With x = c + delta, v = sqrt c: sqrt x = v + delta / (2 v) - delta^2 / (2 v (sqrt x + v)^2)
// exactly, and the last term lies in [-Q, 0], Q = R^2 / (2 v (sqrt X.lo + v)^2): one sqrt
// of the range's lower end (shared with the interval rule) and one division, instead of the
// Lagrange form's f'' at both ends of the range.
vec4 zsa_sqrt(vec4 a, inout bool u) {
  vec2 X = zsa_range(a);
  vec2 I = zsi_sqrt(X, u);
  float v = sqrt(a.x);
  if (!(X.x > 0.0 && X.y < ZSI_INF && v > 16.0 * ZSI_FN_ABS)) return zsa_fromInterval(I);
  float R = zsa_radius(a);
  // Lower bounds of sqrt c and of sqrt X.lo (I.x, outward), so Q is an upper bound.
  float vl = v * (1.0 - 2.0 * ZSI_FN_REL) - 2.0 * ZSI_FN_ABS, sl = I.x + vl;
  float Q = (R * R) / (2.0 * vl * sl * sl) * (1.0 + 8.0 * ZSI_REL);
  float p = 0.5 / v;
  // v and p are off by sqrt's margins (p relative to v's, plus one division).
  float err = v * ZSI_FN_REL + ZSI_FN_ABS + (p * R) * (2.0 * ZSI_FN_REL + 2.0 * ZSI_FN_ABS / vl + ZSI_REL);
  float s = p * a.y;
  vec4 A = zsa_round(vec3(v - 0.5 * Q, s, p * a.z + 0.5 * Q + err), v + Q + abs(s), 2.0 * ZSI_REL);
  return zsa_tighter(A, I);
}
// log where the operand's range lies inside (0, inf), by its first-order Taylor form with
// the Lagrange remainder (log'' = -1/x^2, monotone there, so its range is given by the
// range's ends); its interval rule (and flags) otherwise.
vec4 zsa_log(vec4 a, inout bool u) {
  vec2 X = zsa_range(a);
  vec2 I = zsi_log(X, u);
  if (!(X.x > 0.0 && X.y < ZSI_INF)) return zsa_fromInterval(I);
  float R = zsa_radius(a), v = log(a.x), p = 1.0 / a.x;
  float err = abs(v) * ZSI_FN_REL + ZSI_FN_ABS + p * (2.0 * ZSI_REL);
  vec2 q = zsi_outFn(vec2(-1.0 / (X.x * X.x), -1.0 / (X.y * X.y)), 0.0);  // log'' = -1/x^2
  return zsa_tighter(zsa_taylor(a, R, v, p, err, q), I);
}

// 1/b where b's range X keeps one sign: with x = c + delta, v = 1/c,
// 1/x = v - v^2 delta + v^2 delta^2 / x exactly, and the last term lies between 0 and
// R^2 v^2 / x for the end of X nearest 0 (the interval rule's 1/X, two divisions): three
// divisions in all. Where X holds 0: the whole line, and F may be unbounded (zsi_partial),
// as the interval rule has it.
vec4 zsa_recip(vec4 b) {
  vec2 X = zsa_range(b);
  bool pole = X.x <= 0.0 && X.y >= 0.0;
  zsi_partial = zsi_partial || pole;
  vec2 I = zsi_out(vec2(1.0 / X.y, 1.0 / X.x));  // X of one sign: 1/X, outward
  float R = zsa_radius(b), v = 1.0 / b.x, v2 = v * v;
  float k = R * R * v2 * (1.0 + 8.0 * ZSI_REL);
  // v^2 delta^2 / x in [0, k I.y] (X > 0) or [k I.x, 0] (X < 0): centred.
  float T = X.x > 0.0 ? k * I.y : k * I.x;
  float s = -v2 * b.y;
  // v and v^2 carry one and three roundings; the slope's error times |delta| <= R.
  float r = v2 * b.z + 0.5 * abs(T) + (abs(v) + v2 * R) * (4.0 * ZSI_REL);
  vec4 A = zsa_round(vec3(v + 0.5 * T, s, r), abs(v) + abs(T) + abs(s), 2.0 * ZSI_REL);
  return pole ? zsa_whole() : zsa_tighter(A, I);
}
vec4 zsa_div(vec4 a, vec4 b) {
  vec4 q = zsa_settle(zsa_mul(a, zsa_recip(b)), 1.0);
  return q.z < ZSI_INF ? q : zsa_whole();  // b's range holds 0
}

// x^k by the Taylor form with f'' = k (k - 1) x^(k-2) over the range (the interval rule of
// x^(k-2)), where the range keeps away from 0 for negative k. Squares never come here: the
// emitter writes them as zsa_sqr, a polynomial rule (op_interval_glsl.cpp).
vec4 zsa_powi(vec4 a, int k) {
  if (k == 0) return zsa_const(1.0);
  if (k == 1) return a;
  vec2 X = zsa_range(a);
  vec2 I = zsi_powi(X, k);
  if (k < 0 && X.x <= 0.0 && X.y >= 0.0) return zsa_fromInterval(I);
  float R = zsa_radius(a);
  float v = zsi_ipow(abs(a.x), abs(k));
  v = (abs(k) % 2 == 1 && a.x < 0.0) ? -v : v;
  float pm = zsi_ipow(abs(a.x), abs(k - 1));
  pm = (abs(k - 1) % 2 == 1 && a.x < 0.0) ? -pm : pm;
  if (k < 0) { v = 1.0 / v; pm = 1.0 / pm; }
  float p = float(k) * pm;
  float err = (abs(v) + abs(p)) * (float(abs(k) + 2) * ZSI_REL) + ZSI_TINY;
  vec2 q = float(k * (k - 1)) * zsi_powi(X, k - 2);
  q = zsi_out(vec2(min(q.x, q.y), max(q.x, q.y)));
  return zsa_tighter(zsa_taylor(a, R, v, p, err, q), I);
}

// abs, min and max are exact where the ranges decide them; their interval rules otherwise.
vec4 zsa_abs(vec4 a) {
  vec2 X = zsa_range(a);
  return X.x >= 0.0 ? a : (X.y <= 0.0 ? zsa_neg(a) : zsa_fromInterval(zsi_abs(X)));
}
vec4 zsa_min(vec4 a, vec4 b) {
  vec2 A = zsa_range(a), B = zsa_range(b);
  return A.y <= B.x ? a : (B.y <= A.x ? b : zsa_fromInterval(zsi_min(A, B)));
}
vec4 zsa_max(vec4 a, vec4 b) {
  vec2 A = zsa_range(a), B = zsa_range(b);
  return A.x >= B.y ? a : (B.x >= A.y ? b : zsa_fromInterval(zsi_max(A, B)));
}

// The results of zs_FAffine from the settled forms of F and dF/dt: F's (c, s, r) with r = -1
// (an empty range) where F is defined nowhere, D the range of dF/dt, whole where the gradient
// cannot be bounded.
void zsa_finish(vec4 f, vec4 d, bool u, bool ug, out vec3 F, out vec2 D) {
  F = u ? vec3(0.0, 0.0, -1.0) : f.xyz;
  D = (u || ug) ? vec2(-ZSI_INF, ZSI_INF) : zsa_range(d);
}
