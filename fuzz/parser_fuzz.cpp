// libFuzzer target for the formula front end: any bytes in; the parser must either reject
// them with a printable error or produce a graph whose printed form parses back, whose
// gradient builds, and whose tape evaluates; and the syntax tree of the same text must
// typeset (src/print) into a finite box. Crashes, sanitizer reports and the abort()
// below are findings.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "expr/degree.hpp"
#include "expr/derivative.hpp"
#include "expr/printer.hpp"
#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "print/typeset.hpp"

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

  // The same text as written, typeset with a measure of fixed widths.
  auto syntax = zs::parseSyntax(text);
  auto* tree = std::get_if<zs::SyntaxTree>(&syntax);
  if (!tree || tree->root < 0 || std::size_t(tree->root) >= tree->nodes.size()) std::abort();
  for (std::size_t i = 0; i < tree->nodes.size(); ++i) {
    if (tree->nodes[i].a >= int(i) || tree->nodes[i].b >= int(i)) std::abort();
  }
  const zs::printing::MeasureText measure = [](const std::string& s, bool, double size) {
    return 0.5 * size * double(s.size());
  };
  for (const zs::printing::MathBox& line :
       zs::printing::typesetEquationLines(*tree, 20, measure, 500)) {
    if (!std::isfinite(line.width) || !std::isfinite(line.ascent) || !std::isfinite(line.descent))
      std::abort();
  }
  return 0;
}
