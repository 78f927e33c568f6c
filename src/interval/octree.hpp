#pragma once
// The octree: takes a formula, its parameter values, a domain box and OctreeSettings, puts
// out the kept boxes (leaves) that may hold a point of F = 0, in pre-order (Morton order),
// with per-level statistics. A box is discarded only when interval arithmetic proves
// 0 is not in F(box) (or F is undefined on all of it), so the union of the leaves holds
// every surface point of the domain. A clipping ball (SURFER's sphere) also discards boxes
// that lie wholly outside it.
//
//   thesis:  subdivide a kept box when 0 is in F(box), 0 is in every component of the
//            interval gradient, and its level is below the maximum; otherwise keep it as a
//            leaf (one gradient component has a fixed sign: the surface is a graph there)
//   uniform: subdivide every kept box down to the maximum level
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "expr/graph.hpp"
#include "interval/hierarchy.hpp"
#include "interval/octree_settings.hpp"

namespace zs {

inline constexpr int kMaxOctreeLevel = 20;  // cell indices are 32-bit; 2^20 cells per axis

struct OctreeLeaf {
  Box box;
  int level = 0;
  std::array<std::uint32_t, 3> cell{};  // integer position at its level, 0 .. 2^level - 1
};

struct LevelStats {
  std::size_t tested = 0;  // boxes evaluated at this level
  std::size_t kept = 0;    // of those, boxes where 0 may be in F
  std::size_t leaves = 0;  // of the kept, boxes not subdivided further
};

// A clipping ball: boxes wholly outside it are discarded like boxes where 0 is not in F.
struct Ball {
  std::array<double, 3> center{};
  double radius = 0;
};

// True when no point of `box` lies in the ball (with a relative margin of 1e-12 against the
// rounding of the squared distance): such boxes can be dropped.
bool boxOutsideBall(const Box& box, const Ball& ball);

struct Octree {
  Box domain;
  std::optional<Ball> ball;  // set: the domain is this ball (`domain` its bounding box)
  OctreeSettings settings;
  std::vector<OctreeLeaf> leaves;  // pre-order: a subtree's leaves are contiguous
  std::vector<LevelStats> levels;  // index = level, 0 .. settings.level
  double buildSeconds = 0.0;
  unsigned threads = 1;

  std::size_t testedCount() const;
};

struct OctreeError {
  std::string message;
};

using OctreeResult = std::variant<Octree, OctreeError>;

// The corner coordinate k / 2^level of the domain along one axis. Children share their
// faces bit for bit with each other and with the parent, so the leaves tile exactly.
double cellCoordinate(const Box& domain, int axis, std::uint64_t k, int level);
Box cellBox(const Box& domain, const std::array<std::uint32_t, 3>& cell, int level);

// Never throws for user input: a bad level or domain, or a build that exceeds
// settings.nodeBudget boxes, gives an OctreeError with a message for the user.
// With `ball`, the domain is that ball and `domain` should be its bounding box: boxes wholly
// outside the ball are discarded before F is evaluated on them.
OctreeResult buildOctree(const Formula& formula, std::span<const double> params, const Box& domain,
                         const OctreeSettings& settings, std::optional<Ball> ball = std::nullopt);

}  // namespace zs
