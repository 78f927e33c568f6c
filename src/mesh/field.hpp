#pragma once
// The function the mesh is the zero set of, at points: F, or for a capped ball domain the
// solid {F < 0} cut by the ball, max(F, |p - c| - r). A point is negative when the value is
// < 0; zero and undefined (NaN) count as positive, so the zero set never passes through a
// grid corner. Also the root of the field on a grid edge, and the gradient there.
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "expr/batch_eval.hpp"
#include "expr/tape.hpp"
#include "interval/octree.hpp"

namespace zs::mesh {

using P3 = std::array<double, 3>;

// Not thread-safe (its tapes reuse scratch buffers): one per thread.
class FieldEvaluator {
 public:
  FieldEvaluator(const Tape& value, const Tape& withGradient, std::span<const double> params,
                 std::optional<Ball> capBall);

  // The field at many points at once (the batch evaluator).
  void values(std::span<const double> xs, std::span<const double> ys, std::span<const double> zs,
              std::span<double> out);
  // F and its gradient at p.
  std::array<double, 4> fAndGradient(const P3& p);

  struct Root {
    P3 position{};
    P3 gradient{};        // of the piece that vanishes there (F, or the ball's distance)
    double residual = 0;  // |F| / |grad F| there; 0 on the ball's sphere
    bool onBall = false;  // the ball's sphere, not F, vanishes here (the cap)
    bool pole = false;    // F changes sign here without vanishing (VertexKind::Pole)
  };
  struct Edge {
    P3 a{}, b{};
    double va = 0, vb = 0;  // value(a) < 0 <= value(b), or NaN at b
  };
  // The root of the field on each segment a -> b: bracketed (Illinois), so it never leaves
  // the segment; kept at least kEdgeMargin of the segment away from either end so that no
  // two vertices coincide. The edges are refined side by side, a batch of evaluations per
  // step (edge_roots.cpp).
  void rootsOnEdges(std::span<const Edge> edges, std::span<Root> roots);

 private:
  double ballDistance(const P3& p) const;

  double withBall(const P3& p, double f) const;

  PointEvaluator gradient_;
  BatchEvaluator batch_, batchGradient_;
  std::vector<double> params_;
  std::optional<Ball> capBall_;
};

inline constexpr double kEdgeMargin = 2e-4;

}  // namespace zs::mesh
