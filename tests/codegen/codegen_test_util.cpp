#include "codegen_test_util.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <variant>

#include "parser/parser.hpp"

namespace zs::test {

std::optional<Formula> parseOrFail(std::string_view text) {
  ParseResult parsed = parseFormula(text);
  if (auto* error = std::get_if<ParseError>(&parsed)) {
    ADD_FAILURE() << "formula does not parse:\n" << formatError(text, *error);
    return std::nullopt;
  }
  return std::get<Formula>(std::move(parsed));
}

std::optional<GlslFormula> generate(std::string_view text) {
  std::optional<Formula> formula = parseOrFail(text);
  if (!formula) return std::nullopt;
  return emitFormulaGlsl(*formula);
}

std::filesystem::path sourceDir() {
  if (const char* env = std::getenv("ZS_SOURCE_DIR"); env && *env) return env;
  return ZS_DEFAULT_SOURCE_DIR;
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace zs::test
