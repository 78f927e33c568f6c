#include "interact/kiosk.hpp"

#include <variant>

#include "expr/degree.hpp"
#include "i18n/translate.hpp"
#include "parser/parser.hpp"

namespace zs::interact {

bool kioskAllows(Action action) {
  switch (action) {
    case Action::Quit:
    case Action::Screenshot:
    case Action::WindowShot:
    case Action::SaveScene:
    case Action::ExportMesh:
    case Action::PrintPage:
      return false;
    default:
      return true;
  }
}

std::string kioskRefusal(std::string_view formula, const KioskPolicy& policy) {
  const ParseResult parsed = parseFormula(formula);
  const Formula* f = std::get_if<Formula>(&parsed);
  return f ? kioskRefusal(*f, policy) : "";
}

std::string kioskRefusal(const Formula& f, const KioskPolicy& policy) {
  const std::optional<int> degree = polynomialDegree(f.graph, f.root);
  if (!degree || *degree <= policy.maxDegree) return "";
  return i18n::format(
      i18n::tr("degree %d is more than this exhibit draws (at most %d): try a formula of lower "
               "degree"),
      *degree, policy.maxDegree);
}

}  // namespace zs::interact
