#pragma once
// Meshes a formula for the tests: fails the test on a parse or mesh error.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "mesh/mesh.hpp"
#include "parser/parser.hpp"

namespace zs::testing {

inline MeshResult meshOf(const std::string& formula, const Box& box, int level, bool cap = false,
                         std::optional<Ball> ball = std::nullopt, std::vector<double> params = {}) {
  const ParseResult parsed = parseFormula(formula);
  if (!std::holds_alternative<Formula>(parsed)) {
    ADD_FAILURE() << "does not parse: " << formula;
    return {};
  }
  MeshSettings s;
  s.level = level;
  s.cap = cap;
  auto r = buildMesh(std::get<Formula>(parsed), params, box, ball, s);
  if (auto* e = std::get_if<std::string>(&r)) {
    ADD_FAILURE() << *e;
    return {};
  }
  return std::get<MeshResult>(std::move(r));
}

inline Box cube(double half) {
  return {{-half, -half, -half}, {half, half, half}};
}

}  // namespace zs::testing
