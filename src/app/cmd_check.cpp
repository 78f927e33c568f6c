// `zeroset check FORMULA`: what the formula compiler makes of a formula, without any GL.
#include <iostream>

#include "app/commands.hpp"
#include "app/formula_args.hpp"
#include "expr/degree.hpp"
#include "expr/derivative.hpp"
#include "expr/printer.hpp"
#include "parser/parser.hpp"

namespace zs::app {

namespace {

std::string printed(const Graph& g, NodeId id) {
  return print(g, id).value_or("(too large to print)");
}

int runCheck(const std::string& formula) {
  ParseResult result = parseFormula(formula);
  if (auto* err = std::get_if<ParseError>(&result)) {
    std::cerr << formatError(formula, *err);
    return 1;
  }
  Formula& f = std::get<Formula>(result);
  const std::size_t formulaNodes = reachable(f.graph, {f.root}).size();
  const auto grad = gradient(f.graph, f.root);
  std::cout << "F(x,y,z) = " << printed(f.graph, f.root) << "\n";
  std::cout << "parameters: ";
  if (f.graph.params().empty()) std::cout << "none";
  for (std::size_t i = 0; i < f.graph.params().size(); ++i) {
    std::cout << (i ? ", " : "") << f.graph.params()[i] << " (default " << kDefaultParamValue
              << ")";
  }
  std::cout << "\n";
  if (auto d = polynomialDegree(f.graph, f.root)) {
    std::cout << "degree: " << *d << "\n";
  } else {
    std::cout << "degree: not a polynomial\n";
  }
  const char* names[3] = {"dF/dx", "dF/dy", "dF/dz"};
  for (int k = 0; k < 3; ++k) std::cout << names[k] << " = " << printed(f.graph, grad[k]) << "\n";
  const std::size_t allNodes = reachable(f.graph, {f.root, grad[0], grad[1], grad[2]}).size();
  std::cout << "nodes: " << formulaNodes << " in F, " << allNodes
            << " in F and its gradient together (shared subexpressions counted once)\n";
  if (f.graph.isSpatiallyConstant(f.root)) {
    std::cout << "note: F does not depend on x, y or z, so the surface is empty or everything\n";
  }
  return 0;
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Parse a formula and print what zeroset makes of it");
  auto formula = std::make_shared<std::string>();
  unprotectFormula(
      *cmd->add_option("formula", *formula, "F(x,y,z), e.g. \"x^2 + y^2 + z^2 - 1\"")->required());
  cmd->callback([formula] { std::exit(runCheck(*formula)); });
}

}  // namespace zs::app
