#include "print/page.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <variant>

#include "expr/number_text.hpp"
#include "print/typeset.hpp"

namespace zs::printing {
namespace {

constexpr double kMargin = 42;  // points
constexpr const char* kSerif = "DejaVu Serif";
constexpr const char* kSans = "DejaVu Sans";

using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void setFont(cairo_t* cr, const char* family, bool italic, bool bold, double size) {
  cairo_select_font_face(cr, family, italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double advance(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

// Words of `text` in lines no wider than `width` in the current font.
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double width) {
  std::vector<std::string> lines;
  std::string line, word;
  auto flushWord = [&] {
    if (word.empty()) return;
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && advance(cr, candidate) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = candidate;
    }
    word.clear();
  };
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)))
      flushWord();
    else
      word += c;
  }
  flushWord();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

// Draws `lines` from the baseline at y, centred on the page; returns the next baseline.
double centredLines(cairo_t* cr, const std::vector<std::string>& lines, double pageWidth, double y,
                    double leading) {
  for (const std::string& l : lines) {
    cairo_move_to(cr, (pageWidth - advance(cr, l)) / 2, y);
    cairo_show_text(cr, l.c_str());
    y += leading;
  }
  return y;
}

void drawMath(cairo_t* cr, const MathBox& box, double x, double y) {
  for (const TextRun& r : box.runs) {
    setFont(cr, kSerif, r.italic, false, r.size);
    cairo_move_to(cr, x + r.x, y + r.y);
    cairo_show_text(cr, r.text.c_str());
  }
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Stroke& s : box.strokes) {
    if (s.points.empty()) continue;
    cairo_set_line_width(cr, s.width);
    cairo_move_to(cr, x + s.points[0].first, y + s.points[0].second);
    for (std::size_t i = 1; i < s.points.size(); ++i)
      cairo_line_to(cr, x + s.points[i].first, y + s.points[i].second);
    cairo_stroke(cr);
  }
}

// The formula, typeset at the largest size from 20 pt down to 11 pt that fits `width` on one
// line; a longer one at 11 pt in lines broken between terms, each line that is still too
// wide made smaller (never cut).
std::vector<MathBox> formulaLines(cairo_t* cr, const std::string& formula, double level,
                                  double width) {
  auto tree = parseSyntax(formula);
  const MeasureText measure = [cr](const std::string& text, bool italic, double size) {
    setFont(cr, kSerif, italic, false, size);
    return advance(cr, text);
  };
  SyntaxTree syntax;
  if (auto* t = std::get_if<SyntaxTree>(&tree)) {
    syntax = std::move(*t);
  } else {
    syntax.nodes.push_back({SyntaxNode::Kind::Param, Op::Param, formula});  // as text
    syntax.root = 0;
  }
  if (level != 0) {
    // The level set drawn: F = c, or for F = G, F = G ± |c|.
    const SyntaxNode root = syntax.nodes[std::size_t(syntax.root)];
    const bool equation = root.kind == SyntaxNode::Kind::Equation;
    syntax.nodes.push_back(
        {SyntaxNode::Kind::Number, Op::Const, shortestText(equation ? std::fabs(level) : level)});
    int right = int(syntax.nodes.size()) - 1;
    if (equation) {
      syntax.nodes.push_back(
          {SyntaxNode::Kind::Operation, level > 0 ? Op::Add : Op::Sub, "", root.b, right});
      right = int(syntax.nodes.size()) - 1;
    }
    syntax.nodes.push_back(
        {SyntaxNode::Kind::Equation, Op::Sub, "", equation ? root.a : syntax.root, right});
    syntax.root = int(syntax.nodes.size()) - 1;
  }
  constexpr double kLargest = 20, kSmallest = 11;
  const double oneLine = typesetEquation(syntax, kLargest, measure).width;
  if (oneLine * kSmallest / kLargest <= width) {
    const double size = std::min(kLargest, kLargest * width / oneLine);
    return {typesetEquation(syntax, size, measure)};
  }
  std::vector<MathBox> lines = typesetEquationLines(syntax, kSmallest, measure, width);
  for (MathBox& line : lines) {
    if (line.width <= width) continue;
    line.scale(width / line.width);
  }
  return lines;
}

cairo_surface_t* pictureSurface(const Image& picture) {
  cairo_surface_t* s =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, picture.width, picture.height);
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < picture.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + std::size_t(y) * std::size_t(stride));
    for (int x = 0; x < picture.width; ++x) {
      const std::uint8_t* p = picture.pixel(x, y);
      row[x] = std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
    }
  }
  cairo_surface_mark_dirty(s);
  return s;
}

}  // namespace

PaperSize paperSize(Paper paper) {
  switch (paper) {
    case Paper::A3:
      return {841.89, 1190.55};
    case Paper::Letter:
      return {612, 792};
    case Paper::A4:
      break;
  }
  return {595.28, 841.89};
}

bool parsePaper(const std::string& name, Paper& paper) {
  std::string lower;
  for (char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "a4")
    paper = Paper::A4;
  else if (lower == "a3")
    paper = Paper::A3;
  else if (lower == "letter")
    paper = Paper::Letter;
  else
    return false;
  return true;
}

double pictureSide(Paper paper) {
  return paperSize(paper).width - 2 * kMargin;
}

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool isPageFile(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".pdf" || ext == ".svg";
}

std::string writePage(const std::filesystem::path& path, const PageContent& content, Paper paper) {
  const PaperSize page = paperSize(paper);
  const std::string ext = lowerExtension(path);
  cairo_surface_t* target = nullptr;
  if (ext == ".pdf")
    target = cairo_pdf_surface_create(path.c_str(), page.width, page.height);
  else if (ext == ".svg")
    target = cairo_svg_surface_create(path.c_str(), page.width, page.height);
  else
    return "print: " + path.string() + ": the page is written as .pdf or .svg";
  if (cairo_surface_status(target) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(target));
    cairo_surface_destroy(target);
    return "print: cannot write " + path.string() + ": " + why;
  }
  Context cr(cairo_create(target), cairo_destroy);
  cairo_t* c = cr.get();
  const double textWidth = page.width - 2 * kMargin;
  cairo_set_source_rgb(c, 0.1, 0.1, 0.1);

  // The name and the description.
  double y = kMargin + 22;
  setFont(c, kSans, false, true, 22);
  y = centredLines(c, wrap(c, content.title, textWidth), page.width, y, 28);
  if (!content.description.empty()) {
    setFont(c, kSans, false, false, 11);
    y = centredLines(c, wrap(c, content.description, textWidth), page.width, y + 4, 15);
  }

  // The picture, a square as wide as the text, at its own resolution.
  const double side = pictureSide(paper);
  const double top = y + 6;
  if (content.picture.width > 0 && content.picture.height > 0) {
    cairo_surface_t* picture = pictureSurface(content.picture);
    cairo_save(c);
    cairo_translate(c, kMargin, top);
    cairo_scale(c, side / content.picture.width, side / content.picture.height);
    cairo_set_source_surface(c, picture, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(c), CAIRO_FILTER_BEST);
    cairo_paint(c);
    cairo_restore(c);
    cairo_surface_destroy(picture);
  }
  y = top + side + 14;

  // The formula, centred, and the parameter values under it.
  cairo_set_source_rgb(c, 0, 0, 0);
  for (const auto& [formula, level] : content.formulas) {
    for (const MathBox& line : formulaLines(c, formula, level, textWidth)) {
      y += line.ascent;
      drawMath(c, line, (page.width - line.width) / 2, y);
      y += line.descent + 6;
    }
  }
  y += 14;
  if (!content.params.empty()) {
    std::string values;
    // Six digits, as a person reads them, with a real minus sign.
    for (const auto& [name, value] : content.params) {
      char number[32];
      std::snprintf(number, sizeof number, "%.6g", std::fabs(value));
      values +=
          (values.empty() ? "" : ",   ") + name + " = " + (value < 0 ? "\u2212" : "") + number;
    }
    setFont(c, kSerif, false, false, 12);
    y = centredLines(c, wrap(c, values, textWidth), page.width, y, 16);
  }

  setFont(c, kSans, false, false, 8);
  cairo_set_source_rgb(c, 0.45, 0.45, 0.45);
  centredLines(c, {"drawn by zeroset: the surface F(x, y, z) = 0, ray-traced exactly"}, page.width,
               page.height - kMargin / 2, 10);
  cairo_show_page(c);
  cr.reset();
  cairo_surface_finish(target);
  const cairo_status_t status = cairo_surface_status(target);
  cairo_surface_destroy(target);
  if (status != CAIRO_STATUS_SUCCESS)
    return "print: cannot write " + path.string() + ": " + cairo_status_to_string(status);
  return "";
}

}  // namespace zs::printing
