#pragma once
// Formula typesetting for print (`zeroset print`, docs/print.md): takes a formula's syntax
// tree (parser/parser.hpp parseSyntax: the formula as written) and the font's measure, puts
// out a box of positioned text runs and strokes: x² as a superscript, a/b as a fraction,
// sqrt as a radical, abs as bars, parentheses only where precedence needs them, sized to
// what they hold. The page (page.hpp) draws the box with cairo; the layout itself draws
// nothing, so it is tested with a measure of fixed widths.
#include <functional>
#include <string>
#include <vector>

#include "parser/parser.hpp"

namespace zs::printing {

// Coordinates in points, x to the right, y down from the box's baseline (cairo's).
struct TextRun {
  std::string text;  // UTF-8
  bool italic = false;
  double size = 0;      // font size, points
  double x = 0, y = 0;  // where the run's baseline starts
};

struct Stroke {
  std::vector<std::pair<double, double>> points;  // a polyline
  double width = 0;
};

struct MathBox {
  double width = 0, ascent = 0, descent = 0;  // ascent above, descent below the baseline
  std::vector<TextRun> runs;
  std::vector<Stroke> strokes;
  // Appends `other` moved by (dx, dy), growing the extent to hold it.
  void place(const MathBox& other, double dx, double dy);
  // Everything, text sizes and stroke widths included, `k` times as large.
  void scale(double k);
};

// The advance width of `text` set in the roman or italic face at `size` points.
using MeasureText = std::function<double(const std::string& text, bool italic, double size)>;

// The whole formula as an equation, at `size` points: "F = 0" for a formula, "F = G" for
// one written with '='.
MathBox typesetEquation(const SyntaxTree& tree, double size, const MeasureText& measure);

// The same equation in lines no wider than `width` where it can be: broken before the
// + and − of its outermost sums (a term wider than `width` keeps a line of its own).
std::vector<MathBox> typesetEquationLines(const SyntaxTree& tree, double size,
                                          const MeasureText& measure, double width);

}  // namespace zs::printing
