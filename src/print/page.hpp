#pragma once
// The printed page of a surface (`zeroset print`, the viewer's Print button; docs/print.md):
// takes the picture `zeroset render` draws, the surface's name and description, the formula
// as written and the parameter values; puts out one page, PDF or SVG (cairo), with the
// picture, the formula typeset (typeset.hpp) and the values. Text stays text, so a PDF
// reader can search and copy it.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/image.hpp"

namespace zs::printing {

enum class Paper { A4, A3, Letter };

struct PaperSize {
  double width = 0, height = 0;  // points (1/72 inch), portrait
};
PaperSize paperSize(Paper paper);

// "A4", "A3" or "letter" (any case); false for anything else.
bool parsePaper(const std::string& name, Paper& paper);

// The side, in points, of the square picture on the page: the width between the margins.
double pictureSide(Paper paper);

struct PageContent {
  Image picture;            // square, RGBA8, top row first
  std::string title;        // the surface's name
  std::string description;  // one line or a few sentences
  // One line per surface of the scene: the formula as written (parser/parser.hpp
  // parseSyntax) and its level (the page says F = level).
  std::vector<std::pair<std::string, double>> formulas;
  std::vector<std::pair<std::string, double>> params;
};

// Whether `path` names a page zeroset writes: .pdf or .svg (any case).
bool isPageFile(const std::filesystem::path& path);

// Writes the page to `path`, PDF or SVG by its extension. "" or what went wrong.
std::string writePage(const std::filesystem::path& path, const PageContent& content, Paper paper);

}  // namespace zs::printing
