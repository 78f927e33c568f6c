#include "mesh/field.hpp"

#include <algorithm>
#include <cmath>

namespace zs::mesh {

FieldEvaluator::FieldEvaluator(const Tape& value, const Tape& withGradient,
                               std::span<const double> params, std::optional<Ball> capBall)
    : gradient_(withGradient),
      batch_(value),
      batchGradient_(withGradient),
      params_(params.begin(), params.end()),
      capBall_(capBall) {}

double FieldEvaluator::ballDistance(const P3& p) const {
  const double dx = p[0] - capBall_->center[0], dy = p[1] - capBall_->center[1],
               dz = p[2] - capBall_->center[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - capBall_->radius;
}

double FieldEvaluator::withBall(const P3& p, double v) const {
  if (!capBall_) return v;
  // Outside the ball the solid ends, whatever F says (NaN included).
  const double d = ballDistance(p);
  return d >= 0 ? std::max(d, std::isnan(v) ? d : v) : v;
}

void FieldEvaluator::values(std::span<const double> xs, std::span<const double> ys,
                            std::span<const double> zs, std::span<double> out) {
  batch_.eval(xs, ys, zs, params_, out);
  if (!capBall_) return;
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = withBall({xs[k], ys[k], zs[k]}, out[k]);
}

std::array<double, 4> FieldEvaluator::fAndGradient(const P3& p) {
  std::array<double, 4> out{};
  gradient_.eval(p[0], p[1], p[2], params_, out);
  return out;
}

}  // namespace zs::mesh
