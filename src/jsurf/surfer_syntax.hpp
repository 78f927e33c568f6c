#pragma once
// SURFER's formula language, which is narrower than zeroset's (docs/formula.md): explicit
// '*' only, one-argument functions sin cos tan asin acos atan exp log sqrt ceil floor abs
// sign applied to constants and parameters only, division by constants only, integer
// exponents on anything holding x, y or z, no '=' , no '**', no '[ ]', no sign right after
// '^'. zeroset reads every SURFER formula; this check says whether SURFER can read one of
// ours before `zeroset export` writes it. It follows the grammar of jsurf's
// AlgebraicExpression.g and the checks of its tree walker.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace zs::jsurf {

struct SurferSyntaxError {
  std::size_t offset = 0;  // byte offset into the formula
  std::string message;
};

std::optional<SurferSyntaxError> checkSurferSyntax(std::string_view formula);

}  // namespace zs::jsurf
