#pragma once
// Test helper: the formula a text parses to. A parse error fails the running test and gives
// the constant formula 0, so one bad row cannot crash the whole binary.
#include <gtest/gtest.h>

#include <string>

#include "parser/parser.hpp"

namespace zs::test {

inline Formula parsed(const std::string& text) {
  ParseResult r = parseFormula(text);
  if (auto* e = std::get_if<ParseError>(&r)) {
    ADD_FAILURE() << "does not parse:\n" << formatError(text, *e);
    Formula zero;
    zero.root = zero.graph.constant(0.0);
    return zero;
  }
  return std::get<Formula>(std::move(r));
}

}  // namespace zs::test
