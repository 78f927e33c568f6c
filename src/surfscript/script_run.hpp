#pragma once
// Runs a surf script as surf 1.0.6 does: its globals start at surf's defaults (width 200,
// clip sphere of radius 10, three lights, ...), assignments change them, declarations add
// the script's own variables, and the commands draw and save. What the run leaves is what
// the commands asked for, each with a snapshot of the globals at that moment; turning a
// snapshot into a zeroset Scene is surf_scene.hpp's work. Nothing is drawn or written here.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "surfscript/poly_expr.hpp"
#include "surfscript/script_syntax.hpp"

namespace zs::surfscript {

struct Value {
  enum class Type { Int, Double, Poly, String };
  Type type = Type::Int;
  double number = 0;         // Int, Double
  std::optional<Poly> poly;  // Poly
  std::string text;          // String
};

// surf's globals at one moment.
struct Globals {
  std::map<std::string, Value, std::less<>> values;

  double number(std::string_view name) const;  // 0 for a name that is not a number
  int integer(std::string_view name) const { return static_cast<int>(number(name)); }
  const Poly* poly(std::string_view name) const;  // null when unset or empty
  std::string text(std::string_view name) const;
};

// What surf would do that zeroset does differently, or not at all: said, never dropped.
struct Note {
  Place place;
  std::string message;
};

struct Drawing {
  enum class Kind { Surfaces, Curve };
  Kind kind = Kind::Surfaces;
  Globals globals;  // as they were at the command
  Place place;      // of the command
};

// surf's color_file_format values; png is zeroset's own.
enum class ImageFormat {
  Xwd = 0,
  Sun = 1,
  Ppm = 2,
  Jpeg = 3,
  PostScript = 4,
  Eps = 5,
  Pdf = 6,
  Png = 7
};

struct SavedImage {
  std::vector<Drawing> screen;  // drawn since the last clear_screen, in order
  std::string fileName;
  ImageFormat format = ImageFormat::Sun;
  int width = 200, height = 200;
  Place place;  // of save_color_image
};

struct ScriptRun {
  std::vector<SavedImage> saved;  // one per save_color_image
  std::vector<Drawing> screen;    // what is drawn at the end (since the last clear_screen)
  std::vector<Note> notes;        // in script order
};

std::variant<ScriptRun, ScriptError> runScript(std::string_view text);

// The substitution of surf's rotate(p, angle, axis) (axis 0 x, 1 y, 2 z): about the x axis,
// p(x, c y + s z, -s y + c z), with c = cos(angle), s = sin(angle).
AffineMap surfRotation(double angle, int axis);

}  // namespace zs::surfscript
