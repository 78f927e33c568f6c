#include "mesh/field.hpp"

#include <algorithm>
#include <cmath>

namespace zs::mesh {

FieldEvaluator::FieldEvaluator(const Tape& value, const Tape& withGradient,
                               std::span<const double> params, std::optional<Ball> capBall)
    : value_(value), gradient_(withGradient), params_(params.begin(), params.end()),
      capBall_(capBall) {}

double FieldEvaluator::ballDistance(const P3& p) const {
  const double dx = p[0] - capBall_->center[0], dy = p[1] - capBall_->center[1],
               dz = p[2] - capBall_->center[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - capBall_->radius;
}

double FieldEvaluator::f(const P3& p) { return value_.eval1(p[0], p[1], p[2], params_); }

double FieldEvaluator::value(const P3& p) {
  const double v = f(p);
  if (!capBall_) return v;
  // Outside the ball the solid ends, whatever F says (NaN included).
  const double d = ballDistance(p);
  return d >= 0 ? std::max(d, std::isnan(v) ? d : v) : v;
}

std::array<double, 4> FieldEvaluator::fAndGradient(const P3& p) {
  std::array<double, 4> out{};
  gradient_.eval(p[0], p[1], p[2], params_, out);
  return out;
}

FieldEvaluator::Root FieldEvaluator::rootOnEdge(const P3& a, const P3& b, double va, double vb) {
  auto at = [&](double t) {
    return P3{a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
  };
  // Illinois on the bracket [lo, hi] with value(lo) < 0 <= value(hi); bisection while an
  // end is undefined or infinite.
  double lo = 0, hi = 1, flo = va, fhi = vb;
  const double scale = std::abs(va) + (std::isfinite(vb) ? std::abs(vb) : 0.0);
  double t = 0.5;
  int side = 0;
  for (int it = 0; it < 100 && hi - lo > 1e-12; ++it) {
    if (std::isfinite(flo) && std::isfinite(fhi)) {
      t = lo + (hi - lo) * (flo / (flo - fhi));
      if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    } else {
      t = 0.5 * (lo + hi);
    }
    const double v = value(at(t));
    if (v < 0) {
      lo = t;
      flo = v;
      if (side == -1) fhi *= 0.5;  // Illinois: the stale end's value is halved
      side = -1;
    } else {
      hi = t;
      fhi = v;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
    if (std::abs(v) <= 1e-10 * scale) break;
  }
  t = std::clamp(t, kEdgeMargin, 1 - kEdgeMargin);
  Root r;
  r.position = at(t);
  const std::array<double, 4> fg = fAndGradient(r.position);
  if (capBall_ && ballDistance(r.position) >= (std::isnan(fg[0]) ? -1.0 : fg[0])) {
    // The ball's sphere is the nearer piece here: its gradient is the radial direction.
    r.onBall = true;
    for (std::size_t k = 0; k < 3; ++k) r.gradient[k] = r.position[k] - capBall_->center[k];
    return r;
  }
  r.gradient = {fg[1], fg[2], fg[3]};
  const double g = std::sqrt(fg[1] * fg[1] + fg[2] * fg[2] + fg[3] * fg[3]);
  r.residual = g > 0 ? std::abs(fg[0]) / g : (fg[0] == 0 ? 0.0 : INFINITY);
  return r;
}

}  // namespace zs::mesh
