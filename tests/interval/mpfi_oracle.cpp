#include "mpfi_oracle.hpp"

#include <mpfi.h>
#include <mpfr.h>

#include <cmath>
#include <deque>

namespace zs::test {

namespace {

constexpr mpfr_prec_t kPrec = 128;

// An mpfi_t with RAII, so slots can live in a std::deque.
struct Mi {
  mpfi_t v;
  Mi() { mpfi_init2(v, kPrec); }
  Mi(const Mi&) = delete;
  Mi& operator=(const Mi&) = delete;
  ~Mi() { mpfi_clear(v); }
};

void set(mpfi_ptr r, Interval a) {
  mpfi_interv_d(r, a.lo, a.hi);
}

Interval get(mpfi_srcptr r) {
  if (mpfi_is_empty(r)) return Interval::empty();
  mpfr_t t;
  mpfr_init2(t, kPrec);
  mpfi_get_left(t, r);
  const double lo = mpfr_get_d(t, MPFR_RNDD);
  mpfi_get_right(t, r);
  const double hi = mpfr_get_d(t, MPFR_RNDU);
  mpfr_clear(t);
  return {lo, hi};
}

// x^n over [lo, hi]: the extremes are at the endpoints, plus 0 for even n when 0 is inside.
bool powi(mpfi_ptr r, mpfi_srcptr a, int n) {
  if (n == 0) {
    mpfi_set_si(r, 1);
    return true;
  }
  if (n < 0 && mpfi_has_zero(a)) return false;  // the rule answers an unbounded interval
  mpfr_t e, lo, hi, t;
  mpfr_inits2(kPrec, e, lo, hi, t, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_inf(lo, 1);
  mpfr_set_inf(hi, -1);
  for (int side = 0; side < 2; ++side) {
    side ? mpfi_get_right(e, a) : mpfi_get_left(e, a);
    mpfr_pow_si(t, e, n, MPFR_RNDD);
    mpfr_min(lo, lo, t, MPFR_RNDD);
    mpfr_pow_si(t, e, n, MPFR_RNDU);
    mpfr_max(hi, hi, t, MPFR_RNDU);
  }
  if (n % 2 == 0 && mpfi_has_zero(a)) mpfr_set_zero(lo, 1);
  mpfi_interv_fr(r, lo, hi);
  mpfr_clears(e, lo, hi, t, static_cast<mpfr_ptr>(nullptr));
  return true;
}

// pow(x, y): an integer point exponent is x^n; otherwise, for x >= 0 only, pow is monotone
// in each argument, so its range is spanned by the four corners, each rounded outward.
bool pow(mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) {
  mpfr_t x[2], y[2], lo, hi, t;
  for (auto& v : x) mpfr_init2(v, kPrec);
  for (auto& v : y) mpfr_init2(v, kPrec);
  mpfr_inits2(kPrec, lo, hi, t, static_cast<mpfr_ptr>(nullptr));
  mpfi_get_left(x[0], a);
  mpfi_get_right(x[1], a);
  mpfi_get_left(y[0], b);
  mpfi_get_right(y[1], b);
  bool ok = true;
  if (mpfr_equal_p(y[0], y[1]) && mpfr_integer_p(y[0]) && mpfr_cmp_si(y[0], 1 << 20) <= 0 &&
      mpfr_cmp_si(y[0], -(1 << 20)) >= 0) {
    ok = powi(r, a, int(mpfr_get_si(y[0], MPFR_RNDN)));
  } else if (mpfr_sgn(x[0]) < 0) {
    ok = false;  // negative bases: defined at integer exponents only, no simple oracle
  } else {
    mpfr_set_inf(lo, 1);
    mpfr_set_inf(hi, -1);
    for (auto& u : x)
      for (auto& v : y) {
        mpfr_pow(t, u, v, MPFR_RNDD);
        mpfr_min(lo, lo, t, MPFR_RNDD);
        mpfr_pow(t, u, v, MPFR_RNDU);
        mpfr_max(hi, hi, t, MPFR_RNDU);
      }
    mpfi_interv_fr(r, lo, hi);
  }
  for (auto& v : x) mpfr_clear(v);
  for (auto& v : y) mpfr_clear(v);
  mpfr_clears(lo, hi, t, static_cast<mpfr_ptr>(nullptr));
  return ok;
}

// Intersects a with [lo, hi]; false when that leaves nothing.
bool restrictTo(mpfi_ptr a, double lo, double hi) {
  Mi d;
  mpfi_interv_d(d.v, lo, hi);
  mpfi_intersect(a, a, d.v);
  return !mpfi_is_empty(a);
}

// One operation on MPFI operands (a and b may be modified). Returns false: no oracle.
// An empty result is signalled by *empty.
bool apply(mpfi_ptr r, Op op, mpfi_ptr a, mpfi_ptr b, int ival, double value, bool* empty) {
  *empty = false;
  switch (op) {
    case Op::Const:
      mpfi_set_d(r, value);
      return true;
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
      mpfi_set(r, a);
      return true;
    case Op::Neg:
      mpfi_neg(r, a);
      return true;
    case Op::Add:
      mpfi_add(r, a, b);
      return true;
    case Op::Sub:
      mpfi_sub(r, a, b);
      return true;
    case Op::Mul:
      mpfi_mul(r, a, b);
      return true;
    case Op::Div:
      if (mpfi_has_zero(b)) return false;
      mpfi_div(r, a, b);
      return true;
    case Op::PowI:
      return powi(r, a, ival);
    case Op::Pow:
      return pow(r, a, b);
    case Op::Sin:
      mpfi_sin(r, a);
      return true;
    case Op::Cos:
      mpfi_cos(r, a);
      return true;
    case Op::Tan:
      mpfi_tan(r, a);
      return true;
    case Op::Asin:
      *empty = !restrictTo(a, -1, 1);
      if (!*empty) mpfi_asin(r, a);
      return true;
    case Op::Acos:
      *empty = !restrictTo(a, -1, 1);
      if (!*empty) mpfi_acos(r, a);
      return true;
    case Op::Atan:
      mpfi_atan(r, a);
      return true;
    case Op::Atan2:
      mpfi_atan2(r, a, b);
      return true;
    case Op::Sinh:
      mpfi_sinh(r, a);
      return true;
    case Op::Cosh:
      mpfi_cosh(r, a);
      return true;
    case Op::Tanh:
      mpfi_tanh(r, a);
      return true;
    case Op::Exp:
      mpfi_exp(r, a);
      return true;
    case Op::Log:
      *empty = !restrictTo(a, 0, INFINITY);
      if (!*empty) mpfi_log(r, a);
      return true;
    case Op::Sqrt:
      *empty = !restrictTo(a, 0, INFINITY);
      if (!*empty) mpfi_sqrt(r, a);
      return true;
    case Op::Cbrt:
      mpfi_cbrt(r, a);
      return true;
    case Op::Abs:
      mpfi_abs(r, a);
      return true;
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
    case Op::Min:
    case Op::Max:
      return false;
    case Op::IfDefined:
      return false;  // definedness, not arithmetic
  }
  return false;
}

}  // namespace

std::optional<Interval> mpfiApply(Op op, Interval a, Interval b, int ival, double value) {
  if (a.isEmpty() || b.isEmpty()) return Interval::empty();
  Mi r, ma, mb;
  set(ma.v, a);
  set(mb.v, b);
  bool empty = false;
  if (!apply(r.v, op, ma.v, mb.v, ival, value, &empty)) return std::nullopt;
  if (empty) return Interval::empty();
  return get(r.v);
}

std::optional<std::vector<Interval>> mpfiTape(const Tape& tape, const Box& box,
                                              std::span<const double> params) {
  std::deque<Mi> slots(tape.code.size());
  std::vector<bool> empty(tape.code.size(), false);
  Mi scratchA, scratchB;
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    const Instr& in = tape.code[i];
    const int arity = opInfo(in.op).arity;
    if ((arity >= 1 && empty[std::size_t(in.a)]) || (arity >= 2 && empty[std::size_t(in.b)])) {
      empty[i] = true;
      continue;
    }
    if (arity >= 1) mpfi_set(scratchA.v, slots[std::size_t(in.a)].v);
    if (arity >= 2) mpfi_set(scratchB.v, slots[std::size_t(in.b)].v);
    if (in.op == Op::VarX) set(scratchA.v, {box.min[0], box.max[0]});
    if (in.op == Op::VarY) set(scratchA.v, {box.min[1], box.max[1]});
    if (in.op == Op::VarZ) set(scratchA.v, {box.min[2], box.max[2]});
    if (in.op == Op::Param) mpfi_set_d(scratchA.v, params[std::size_t(in.ival)]);
    bool e = false;
    if (!apply(slots[i].v, in.op, scratchA.v, scratchB.v, in.ival, in.value, &e))
      return std::nullopt;
    empty[i] = e;
  }
  std::vector<Interval> out;
  for (std::int32_t s : tape.outputs)
    out.push_back(empty[std::size_t(s)] ? Interval::empty() : get(slots[std::size_t(s)].v));
  return out;
}

}  // namespace zs::test
