#pragma once
// Singular points of F = 0: takes a formula, its parameter values and the domain (a box, and
// optionally a clipping ball), puts out the real points where F = 0 and grad F = 0 that
// interval arithmetic certifies, and the boxes it could not decide. docs/singular.md has
// the method and its guarantees:
//  - a box where 0 is not in F or not in every component of the interval gradient holds no
//    singular point and is dropped (outward-rounded intervals, src/interval);
//  - a box for which the Krawczyk operator of grad F maps (a slightly inflated copy of) the
//    box into its own interior holds exactly one zero of grad F; it is refined by Newton's
//    method and kept as a singular point when 0 is in F over the Krawczyk box and |F| at the
//    refined point is within `fTolerance`;
//  - boxes narrower than `minWidth` of the domain that are neither dropped nor certified
//    (degenerate singularities, curves of singular points such as the Whitney umbrella's
//    axis) are reported as uncertified regions, never dropped silently.
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "expr/graph.hpp"
#include "interval/hierarchy.hpp"
#include "interval/octree.hpp"

namespace zs {

struct SingularSettings {
  int maxDepth = 14;         // halvings of the domain per axis before a box is uncertified
  double fTolerance = 1e-8;  // |F| at a certified critical point, relative to max(1, |F| scale)
  std::size_t boxBudget = 4'000'000;  // boxes tested before giving up with an error
};

struct SingularPoint {
  std::array<double, 3> point{};
  double boxWidth = 0;                       // widest side of the box the Krawczyk test certified
  double f = 0;                              // F at the point (zero to the tolerance)
  std::array<double, 3> eigenvalues{};       // of the Hessian at the point, ascending
  int positive = 0, negative = 0, zero = 0;  // its signature (zero: |lambda| tiny)
  // Non-degenerate Hessian: an ordinary double point (node, A1).
  bool isNode() const { return zero == 0; }
};

struct SingularResult {
  std::vector<SingularPoint> points;  // ordered by x, then y, then z
  std::vector<Box> uncertified;       // boxes left undecided at the maximum depth
  std::size_t boxesTested = 0;
  double seconds = 0;
};

std::variant<SingularResult, std::string> findSingularPoints(const Formula& formula,
                                                             std::span<const double> params,
                                                             const Box& domain,
                                                             std::optional<Ball> ball,
                                                             const SingularSettings& settings);

}  // namespace zs
