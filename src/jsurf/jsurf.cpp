#include "jsurf/jsurf.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "expr/degree.hpp"
#include "expr/number_text.hpp"
#include "expr/printer.hpp"
#include "jsurf/read_surfer.hpp"
#include "jsurf/scene_mapping.hpp"
#include "jsurf/surfer_syntax.hpp"
#include "jsurf/write_surfer.hpp"
#include "parser/parser.hpp"

namespace zs::jsurf {

ImportResult importJsurf(std::string_view text, std::string_view fileName) {
  auto read = readSurferScene(text, fileName);
  if (auto* err = std::get_if<SceneError>(&read)) return *err;
  SurferRead& r = std::get<SurferRead>(read);
  Imported out;
  out.warnings = std::move(r.warnings);
  std::vector<std::string> notes;
  out.scene = toScene(r.scene, notes);
  for (std::string& n : notes) {
    SceneError w;
    w.file = std::string(fileName);
    w.message = std::move(n);
    out.warnings.push_back(std::move(w));
  }
  // A failure here is a bug in the mapping, said as such rather than passed on.
  if (auto err = checkImportedScene(out.scene, fileName, ".jsurf")) return *err;
  return out;
}

ImportResult loadJsurf(const std::filesystem::path& path) {
  auto text = readSceneFile(path, ".jsurf file");
  if (auto* err = std::get_if<SceneError>(&text)) return *err;
  return importJsurf(std::get<std::string>(text), path.string());
}

bool isJsurfPath(std::string_view path) {
  constexpr std::string_view ext = ".jsurf";
  if (path.size() < ext.size()) return false;
  return std::equal(
      ext.begin(), ext.end(), path.end() - static_cast<std::ptrdiff_t>(ext.size()),
      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

namespace {

// The formula as SURFER must see it: the scene's own text when SURFER reads it, else
// zeroset's normal form of it when SURFER reads that; otherwise why not.
struct SurferFormula {
  std::string text;
  std::string error;  // empty when text is good
};

SurferFormula surferFormula(const std::string& formula, std::vector<std::string>& notes) {
  const ParseResult parsed = parseFormula(formula);
  if (const auto* err = std::get_if<ParseError>(&parsed)) return {{}, formatError(formula, *err)};
  const Formula& f = std::get<Formula>(parsed);
  if (!polynomialDegree(f.graph, f.root))
    return {{}, "SURFER draws polynomials in x, y and z only; this formula is not one\n"};
  const auto problem = checkSurferSyntax(formula);
  if (!problem) return {formula, {}};
  if (auto printed = print(f.graph, f.root); printed && !checkSurferSyntax(*printed)) {
    notes.push_back("the formula is written in SURFER's syntax as " + *printed);
    return {*printed, {}};
  }
  ParseError shown{{problem->offset, problem->offset + 1}, problem->message, ""};
  return {{}, formatError(formula, shown)};
}

}  // namespace

std::variant<Exported, std::string> exportJsurf(const Scene& scene) {
  if (surfaceCount(scene) > 1) {
    return "error: cannot export to SURFER: this scene has " + std::to_string(surfaceCount(scene)) +
           " surfaces, and a SURFER scene draws one\n"
           "hint: export one surface at a time (keep one [[surface]]), or draw their union as "
           "one formula, the product F*G\n";
  }
  Exported out;
  // SURFER draws F = 0: a level c is exported as the formula (F) - (c).
  std::string text = scene.formula;
  if (scene.level != 0) {
    text = "(" + scene.formula + ") - (" + shortestText(scene.level) + ")";
    out.warnings.push_back("surface.level " + shortestText(scene.level) +
                           " is written into the formula: SURFER has no level");
  }
  const auto planes = std::count_if(scene.render.clipPlanes.begin(), scene.render.clipPlanes.end(),
                                    [](const ClipPlane& p) { return p.enabled; });
  if (planes > 0)
    out.warnings.push_back(std::to_string(planes) + " clip plane" + (planes > 1 ? "s are" : " is") +
                           " left out: SURFER has no cross-sections");
  const SurferFormula formula = surferFormula(text, out.warnings);
  if (!formula.error.empty()) return "error: cannot export to SURFER:\n" + formula.error;
  SurferScene s = toSurferScene(scene, out.warnings);
  s.formula = formula.text;
  if (std::abs(s.view.scaleFactor) > 2)
    out.warnings.push_back(
        "SURFER's zoom goes from a clipping radius of 0.01 to 100; it will clamp this one");
  out.text = writeSurferScene(s);
  return out;
}

std::string formatWarning(const SceneError& warning) {
  return formatSceneWarning(warning);
}

}  // namespace zs::jsurf
