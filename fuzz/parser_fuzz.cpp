// libFuzzer target for the formula front end: any bytes in; the parser must either reject
// them with a printable error or produce a graph whose printed form parses back, whose
// gradient builds, and whose tape evaluates. Crashes, sanitizer reports and the abort()
// below are findings.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "expr/degree.hpp"
#include "expr/derivative.hpp"
#include "expr/printer.hpp"
#include "expr/tape.hpp"
#include "parser/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  zs::ParseResult result = zs::parseFormula(text);
  if (auto* err = std::get_if<zs::ParseError>(&result)) {
    if (err->span.begin > text.size() || err->span.end < err->span.begin) std::abort();
    (void)zs::formatError(text, *err);
    return 0;
  }
  zs::Formula& f = std::get<zs::Formula>(result);
  if (auto printed = zs::print(f.graph, f.root, 1 << 16)) {
    if (!std::holds_alternative<zs::Formula>(zs::parseFormula(*printed))) std::abort();
  }
  const auto grad = zs::gradient(f.graph, f.root);
  (void)zs::polynomialDegree(f.graph, f.root);
  zs::PointEvaluator ev(zs::compileTape(f.graph, {f.root, grad[0], grad[1], grad[2]}));
  std::vector<double> params(f.graph.params().size(), 0.5);
  double out[4];
  ev.eval(0.25, -0.5, 0.75, params, out);
  return 0;
}
