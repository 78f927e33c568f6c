#include "surfaces.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "parser/parser.hpp"

namespace zs::test {

Formula parseOrDie(std::string_view text) {
  ParseResult r = parseFormula(text);
  if (auto* e = std::get_if<ParseError>(&r)) {
    std::fprintf(stderr, "%s\n", formatError(text, *e).c_str());
    std::abort();
  }
  return std::move(std::get<Formula>(r));
}

}  // namespace zs::test
