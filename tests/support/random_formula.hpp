#pragma once
// Random valid formulas for tests and fuzzing: takes a seeded std::mt19937_64 and options,
// puts out formula TEXT in zeroset's language (docs/formula.md) that the parser accepts:
// numbers in every spelling (2, 2.5, .5, 1e-3), x y z, pi, e, parameters, + - * / ^ and **,
// unary minus and plus, every function of the opcode table, implicit multiplication (2x,
// (x+1)(y-1), 2 pi, x y, x sin(y)), ( ) and [ ] groups, integer, negative and real
// exponents, and sometimes one '='.
//
// Deterministic on every platform: only the engine's raw output is used (no std
// distributions, whose results differ between standard libraries), and every draw happens
// in a fixed order. Recursion depth is bounded by maxDepth (clamped to kMaxRandomDepth).
#include <cstdint>
#include <random>
#include <string>

namespace zs::test {

inline constexpr int kMaxRandomDepth = 48;

struct RandomFormulaOptions {
  int maxDepth = 5;                  // operations nested at most this deep
  int paramCount = 2;                // parameters drawn from a, b, c, k, r, s, alpha, ... (<= 10)
  int maxIntegerExponent = 12;       // literal integer exponents in [-max, max]
  double equalsProbability = 0.15;   // "lhs = rhs" instead of one expression
  double implicitProbability = 0.3;  // a product written without '*'
  double leafProbability = 0.2;      // stop early (before maxDepth) with a leaf
};

std::string randomFormula(std::mt19937_64& rng, const RandomFormulaOptions& options = {});

}  // namespace zs::test
