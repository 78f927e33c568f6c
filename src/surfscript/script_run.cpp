#include "surfscript/script_run.hpp"

#include <cmath>
#include <functional>
#include <string>

#include "expr/number_text.hpp"
#include "parser/suggest.hpp"

namespace zs::surfscript {

AffineMap surfRotation(double angle, int axis) {
  const double c = std::cos(angle), s = std::sin(angle);
  AffineMap m = identityMap();
  const int i = axis == 0 ? 1 : 0;  // the two coordinates that turn: (i, j)
  const int j = axis == 2 ? 1 : 2;
  m[i] = {0, 0, 0, 0};
  m[j] = {0, 0, 0, 0};
  m[i][i] = c;
  m[i][j] = s;
  m[j][i] = -s;
  m[j][j] = c;
  return m;
}

double Globals::number(std::string_view name) const {
  auto it = values.find(name);
  if (it == values.end() ||
      (it->second.type != Value::Type::Int && it->second.type != Value::Type::Double))
    return 0;
  return it->second.number;
}

const Poly* Globals::poly(std::string_view name) const {
  auto it = values.find(name);
  if (it == values.end() || it->second.type != Value::Type::Poly || !it->second.poly)
    return nullptr;
  return &*it->second.poly;
}

std::string Globals::text(std::string_view name) const {
  auto it = values.find(name);
  return it == values.end() || it->second.type != Value::Type::String ? std::string()
                                                                      : it->second.text;
}

namespace {

Value intValue(double v) {
  return {Value::Type::Int, v, std::nullopt, {}};
}
Value doubleValue(double v) {
  return {Value::Type::Double, v, std::nullopt, {}};
}
Value polyValue(Poly p) {
  return {Value::Type::Poly, 0, std::move(p), {}};
}
Value stringValue(std::string s) {
  return {Value::Type::String, 0, std::nullopt, std::move(s)};
}

const char* typeName(Value::Type t) {
  switch (t) {
    case Value::Type::Int:
      return "an integer";
    case Value::Type::Double:
      return "a number";
    case Value::Type::Poly:
      return "a polynomial";
    case Value::Type::String:
      return "a string";
  }
  return "a value";
}

// surf's globals with their defaults (surf 1.0.6's addDefaultSymbols; docs/surf.md).
std::map<std::string, Value, std::less<>> defaultGlobals() {
  std::map<std::string, Value, std::less<>> g;
  auto i = [&](const std::string& n, double v) { g[n] = intValue(v); };
  auto d = [&](const std::string& n, double v) { g[n] = doubleValue(v); };
  auto p = [&](const std::string& n) { g[n] = {Value::Type::Poly, 0, std::nullopt, {}}; };
  i("width", 200);
  i("height", 200);
  for (int s = 1; s <= 9; ++s) {
    const std::string k = s == 1 ? "" : std::to_string(s);
    p("surface" + k);
    i("surface" + k + "_red", 123);
    i("surface" + k + "_green", 104);
    i("surface" + k + "_blue", 238);
    i("inside" + k + "_red", 230);
    i("inside" + k + "_green", 180);
    i("inside" + k + "_blue", 30);
    i("ambient" + k, 25);
    i("diffuse" + k, 60);
    i("reflected" + k, 70);
    i("transmitted" + k, 50);
    i("smoothness" + k, 20);
    i("transparence" + k, 80);
    i("thickness" + k, 10);
  }
  i("illumination", 7);
  const double lightXY[9][2] = {{-100, 100}, {0, 100},     {100, 100}, {-100, 0},  {0, 0},
                                {100, 0},    {-100, -100}, {0, -100},  {100, -100}};
  for (int l = 1; l <= 9; ++l) {
    const std::string k = "light" + std::to_string(l);
    d(k + "_x", lightXY[l - 1][0]);
    d(k + "_y", lightXY[l - 1][1]);
    d(k + "_z", 100);
    i(k + "_vol", l == 1 ? 50 : l == 3 ? 70 : l == 8 ? 30 : 0);
    i(k + "_red", 255);
    i(k + "_green", 255);
    i(k + "_blue", 255);
  }
  for (const char* c : {"background_red", "background_green", "background_blue"}) i(c, 0);
  i("do_background", 0);  // yes
  i("gradient", 0);
  i("gradient_red", 0);
  i("gradient_green", 0);
  i("gradient_blue", 255);
  for (const char* c : {"origin_x", "origin_y", "origin_z", "rot_x", "rot_y", "rot_z", "center_x",
                        "center_y", "center_z"})
    d(c, 0);
  for (const char* c : {"scale_x", "scale_y", "scale_z"}) d(c, 1);
  d("spec_z", 25);
  i("perspective", 0);  // parallel
  i("first", 0);
  i("second", 1);
  i("third", 2);
  i("normalize_brightness", 0);
  d("normalize_factor", 1);
  i("antialiasing", 1);
  d("antialiasing_threshold", 0.1);
  d("antialiasing_radius", 2);
  i("depth_cueing", 0);
  d("depth", -14);
  i("stereo_eye", 0);
  d("stereo_z", 5);
  d("stereo_red", 1);
  d("stereo_green", 0.7);
  d("stereo_blue", 0);
  i("optimize_colors", 0);
  i("dither_colors", 0);
  i("dither_steps", 20);
  i("root_finder", 0);
  d("epsilon", 0.0001);
  i("iterations", 200);
  i("clip", 0);  // sphere
  d("clip_front", 10);
  d("clip_back", -10);
  d("radius", 10);
  p("curve");
  p("plane");
  for (int c = 1; c <= 12; ++c) p(c == 1 ? "clip_surface" : "clip_surface" + std::to_string(c));
  d("curve_width", 3);
  d("curve_gamma", 1.4);
  i("curve_red", 255);
  i("curve_green", 255);
  i("curve_blue", 255);
  i("surf_nr", 1);
  i("surface_n", 1);
  d("cut_distance", 0.0001);
  i("color_file_format", 1);  // sun
  i("color_file_colormap", 0);
  i("dither_file_format", 6);
  g["filename"] = stringValue("");
  return g;
}

// surf's named constants.
const std::map<std::string, int, std::less<>>& constants() {
  static const std::map<std::string, int, std::less<>> c = {
      {"xAxis", 0},
      {"yAxis", 1},
      {"zAxis", 2},
      {"ambient_light", 1},
      {"diffuse_light", 2},
      {"reflected_light", 4},
      {"transmitted_light", 8},
      {"yes", 0},
      {"no", 1},
      {"parallel", 0},
      {"central", 1},
      {"translate", 0},
      {"rotate", 1},
      {"scale", 2},
      {"sphere", 0},
      {"tetrahedron", 1},
      {"cube", 2},
      {"octahedron", 3},
      {"dodecahedron", 4},
      {"icosahedron", 5},
      {"cylinder", 6},
      {"user", 7},
      {"none", 8},
      {"xwd", 0},
      {"sun", 1},
      {"ppm", 2},
      {"jpg", 3},
      {"postscript_color", 4},
      {"encapsulatedpostscript_color", 5},
      {"pdf_color", 6},
      {"png", 7},
      {"TrueColor", 0},
      {"Netscape", 1},
      {"Optimized", 2},
      {"bezier_all_roots", 0},
      {"d_chain_bisection", 1},
      {"d_chain_regula_falsi", 2},
      {"d_chain_pegasus", 3},
      {"d_chain_anderson_bjoerck", 4},
      {"d_chain_newton", 5},
      {"postscript", 0},
      {"encapsulated", 1},
      {"X11_bitmap", 2},
      {"tiff", 3},
      {"pgm", 5},
      {"pbm", 6},
  };
  return c;
}

// Commands zeroset runs, and surf's others, which it names in a note.
enum class Command { DrawSurface, DrawCurve, Save, Clear, SetSize, Other };

std::optional<Command> commandOf(std::string_view name) {
  if (name == "draw_surface") return Command::DrawSurface;
  if (name == "draw_curve") return Command::DrawCurve;
  if (name == "save_color_image") return Command::Save;
  if (name == "clear_screen" || name == "clear_pixmap") return Command::Clear;
  if (name == "set_size") return Command::SetSize;
  for (const char* other : {"cut_with_plane", "cut_with_surface", "dither_surface", "dither_curve",
                            "save_dithered_image", "resultant"})
    if (name == other) return Command::Other;
  return std::nullopt;
}

struct Failure {
  ScriptError error;
};

class Runner {
 public:
  Runner() : globals_{defaultGlobals()} {}

  ScriptRun run(const std::vector<Statement>& statements) {
    for (const Statement& s : statements) statement(s);
    out_.screen = screen_;
    return std::move(out_);
  }

 private:
  [[noreturn]] static void fail(const Place& place, std::string message, std::string hint = {}) {
    throw Failure{{place, std::move(message), std::move(hint)}};
  }

  void note(const Place& place, std::string message) {
    for (const Note& n : out_.notes)
      if (n.message == message) return;  // once is enough
    out_.notes.push_back({place, std::move(message)});
  }

  std::vector<std::string_view> knownNames() const {
    std::vector<std::string_view> names;
    for (const auto& [name, v] : globals_.values) names.push_back(name);
    for (const auto& [name, v] : locals_) names.push_back(name);
    return names;
  }

  std::string didYouMean(std::string_view word, std::vector<std::string_view> names) const {
    // One letter off at most in short names: 'b' is not a misspelt 'no'.
    if (auto best = closestName(word, names, word.size() <= 3 ? 1 : 2))
      return "did you mean " + *best + "?";
    return {};
  }

  // Where an expression's text starts: its leftmost part.
  static Place startOf(const Expr& e) {
    if ((e.kind == Expr::Kind::Binary) && !e.args.empty()) return startOf(e.args[0]);
    return e.place;
  }

  void statement(const Statement& s) {
    switch (s.kind) {
      case Statement::Kind::Declare:
        declare(s);
        return;
      case Statement::Kind::Assign:
        assign(s);
        return;
      case Statement::Kind::Command:
        command(s);
        return;
    }
  }

  void declare(const Statement& s) {
    if (globals_.values.count(s.name) || constants().count(s.name) || commandOf(s.name))
      fail(s.namePlace, "'" + s.name + "' is one of surf's own names",
           "pick another name for the variable");
    if (s.name == "x" || s.name == "y" || s.name == "z")
      fail(s.namePlace, "x, y and z are the coordinates", "pick another name for the variable");
    if (locals_.count(s.name))
      fail(s.namePlace, "'" + s.name + "' is declared twice",
           "declare each variable once; assign it again with " + s.name + " = ...;");
    Value v;
    if (s.type == "int")
      v = intValue(0);
    else if (s.type == "double")
      v = doubleValue(0);
    else if (s.type == "poly")
      v = {Value::Type::Poly, 0, std::nullopt, {}};
    else
      v = stringValue("");
    locals_[s.name] = v;
    if (s.hasValue) store(locals_[s.name], s.name, evaluate(s.value), startOf(s.value));
  }

  void assign(const Statement& s) {
    Value* slot = nullptr;
    if (auto it = locals_.find(s.name); it != locals_.end())
      slot = &it->second;
    else if (auto g = globals_.values.find(s.name); g != globals_.values.end())
      slot = &g->second;
    if (!slot) {
      if (commandOf(s.name))
        fail(s.namePlace, "'" + s.name + "' is a command", "write it alone: " + s.name + ";");
      std::string hint = didYouMean(s.name, knownNames());
      if (hint.empty())
        hint = "declare it first: double " + s.name + " = ...; (or poly, int, string)";
      fail(s.namePlace, "unknown variable '" + s.name + "'", hint);
    }
    store(*slot, s.name, evaluate(s.value), startOf(s.value));
  }

  // Puts `v` into a variable of `slot`'s type, converting as surf does.
  void store(Value& slot, const std::string& name, Value v, const Place& place) {
    switch (slot.type) {
      case Value::Type::Int:
        if (v.type == Value::Type::Double && v.number == std::floor(v.number) &&
            std::abs(v.number) < 2e9) {
          slot.number = v.number;  // surf insists on 100 rather than 100.0; zeroset takes either
          return;
        }
        if (v.type != Value::Type::Int)
          fail(place, name + " is an integer; this is " + typeName(v.type),
               v.type == Value::Type::Double
                   ? "round it: surf's integer settings take whole numbers"
                   : "give it a whole number");
        slot.number = v.number;
        return;
      case Value::Type::Double:
        if (v.type != Value::Type::Int && v.type != Value::Type::Double)
          fail(place, name + " is a number; this is " + typeName(v.type),
               v.type == Value::Type::Poly
                   ? "a polynomial goes into surface, curve or a poly variable"
                   : "");
        slot.number = v.number;
        return;
      case Value::Type::Poly:
        if (v.type == Value::Type::String) fail(place, name + " is a polynomial; this is a string");
        slot.poly = v.type == Value::Type::Poly ? *v.poly : Poly::constant(v.number);
        return;
      case Value::Type::String:
        if (v.type != Value::Type::String)
          fail(place, name + " is a string; this is " + typeName(v.type),
               "write it in double quotes: \"...\"");
        slot.text = v.text;
        return;
    }
  }

  void command(const Statement& s) {
    const auto c = commandOf(s.name);
    if (!c) {
      if (globals_.values.count(s.name) || locals_.count(s.name))
        fail(s.namePlace, "'" + s.name + "' is a variable, not a command",
             "give it a value: " + s.name + " = ...;");
      std::vector<std::string_view> names{"draw_surface", "draw_curve",   "save_color_image",
                                          "clear_screen", "clear_pixmap", "set_size"};
      std::string hint = didYouMean(s.name, names);
      if (hint.empty())
        hint = "the commands are draw_surface, draw_curve, save_color_image and clear_screen";
      fail(s.namePlace, "unknown command '" + s.name + "'", hint);
    }
    switch (*c) {
      case Command::DrawSurface:
        screen_.push_back({Drawing::Kind::Surfaces, globals_, s.place});
        return;
      case Command::DrawCurve:
        screen_.push_back({Drawing::Kind::Curve, globals_, s.place});
        return;
      case Command::Clear:
        screen_.clear();
        return;
      case Command::SetSize:
        return;  // surf takes the size at each drawing
      case Command::Save:
        save(s);
        return;
      case Command::Other:
        note(s.place, s.name + " is not done by zeroset: the command is skipped");
        return;
    }
  }

  void save(const Statement& s) {
    SavedImage image;
    image.fileName = globals_.text("filename");
    if (image.fileName.empty())
      fail(s.place, "save_color_image needs a file name",
           "set filename = \"picture.jpg\"; before it");
    if (image.fileName[0] == '|')
      fail(s.place, "zeroset does not pipe pictures to commands (filename starts with '|')",
           "write the picture to a file and run the command on it");
    const int format = globals_.integer("color_file_format");
    if (format != 1 && format != 2 && format != 3 && format != 7)
      fail(s.place,
           "zeroset writes jpg, ppm, sun and png pictures, not color_file_format " +
               std::to_string(format),
           "set color_file_format = jpg; (or ppm, sun, png)");
    image.format = static_cast<ImageFormat>(format);
    image.width = globals_.integer("width") > 0 ? globals_.integer("width") : 200;
    image.height = globals_.integer("height") > 0 ? globals_.integer("height") : 200;
    image.screen = screen_;
    image.place = s.place;
    out_.saved.push_back(std::move(image));
  }

  // --- expressions ---

  Value evaluate(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::Number:
        return e.integer ? intValue(e.number) : doubleValue(e.number);
      case Expr::Kind::String:
        return stringValue(e.text);
      case Expr::Kind::Name:
        return name(e);
      case Expr::Kind::Call:
        return call(e);
      case Expr::Kind::Negate: {
        Value v = evaluate(e.args[0]);
        if (v.type == Value::Type::Poly) return polyValue(-*v.poly);
        if (v.type == Value::Type::String) fail(e.place, "a string has no sign");
        v.number = -v.number;
        return v;
      }
      case Expr::Kind::Binary:
        return binary(e);
    }
    fail(e.place, "unexpected expression");
  }

  Value name(const Expr& e) {
    if (e.text == "x") return polyValue(Poly::variable(0));
    if (e.text == "y") return polyValue(Poly::variable(1));
    if (e.text == "z") return polyValue(Poly::variable(2));
    if (auto it = locals_.find(e.text); it != locals_.end()) return readable(it->second, e);
    if (auto it = globals_.values.find(e.text); it != globals_.values.end())
      return readable(it->second, e);
    if (auto it = constants().find(e.text); it != constants().end()) return intValue(it->second);
    std::vector<std::string_view> names = knownNames();
    for (const auto& [n, v] : constants()) names.push_back(n);
    std::string hint = didYouMean(e.text, names);
    if (hint.empty()) hint = "declare it first: double " + e.text + " = ...;";
    fail(e.place, "unknown name '" + e.text + "'", hint);
  }

  Value readable(const Value& v, const Expr& e) {
    if (v.type == Value::Type::Poly && !v.poly)
      fail(e.place, "'" + e.text + "' has no polynomial yet",
           "give it one first: " + e.text + " = ...;");
    return v;
  }

  static bool isNumber(const Value& v) {
    return v.type == Value::Type::Int || v.type == Value::Type::Double;
  }

  // Bounds on what a polynomial may grow to: zeroset draws degrees far below these, and the
  // tree is walked recursively.
  static constexpr int kMaxDegree = 1000;
  static constexpr int kMaxDepth = 2000;

  Value checked(Value v, const Expr& e) {
    if (v.type != Value::Type::Poly) return v;
    if (v.poly->depth() > kMaxDepth)
      fail(e.place,
           "this polynomial is nested too deeply (over " + std::to_string(kMaxDepth) + " levels)",
           "write it in fewer operations, or expanded");
    if (v.poly->degree() > kMaxDegree)
      fail(e.place, "this polynomial's degree is over " + std::to_string(kMaxDegree),
           "zeroset draws surfaces of far lower degree");
    return v;
  }

  Value binary(const Expr& e) { return checked(binaryUnchecked(e), e); }

  Value binaryUnchecked(const Expr& e) {
    const Value a = evaluate(e.args[0]);
    const Value b = evaluate(e.args[1]);
    const char op = e.op;
    if (a.type == Value::Type::String || b.type == Value::Type::String) {
      if (op == '+' && a.type == Value::Type::String && b.type == Value::Type::String)
        return stringValue(a.text + b.text);
      fail(e.place,
           std::string("strings are joined with +, not combined with numbers by '") + op + "'",
           "turn a number into text with itostr(n)");
    }
    if (isNumber(a) && isNumber(b)) {
      const bool ints = a.type == Value::Type::Int && b.type == Value::Type::Int;
      switch (op) {
        case '+':
          return ints ? intValue(a.number + b.number) : doubleValue(a.number + b.number);
        case '-':
          return ints ? intValue(a.number - b.number) : doubleValue(a.number - b.number);
        case '*':
          return ints ? intValue(a.number * b.number) : doubleValue(a.number * b.number);
        case '/':
          if (b.number == 0) fail(e.place, "division by zero", "the divisor here is 0");
          return doubleValue(a.number / b.number);  // surf: 1/2 is 0.5
        case '^':
          if (ints) return intValue(std::trunc(std::pow(a.number, b.number)));  // surf: 2^-1 is 0
          return doubleValue(std::pow(a.number, b.number));
      }
    }
    // A polynomial on one side at least.
    const Poly pa = a.type == Value::Type::Poly ? *a.poly : Poly::constant(a.number);
    switch (op) {
      case '+':
        return polyValue(pa + (b.type == Value::Type::Poly ? *b.poly : Poly::constant(b.number)));
      case '-':
        return polyValue(pa - (b.type == Value::Type::Poly ? *b.poly : Poly::constant(b.number)));
      case '*':
        return polyValue(pa * (b.type == Value::Type::Poly ? *b.poly : Poly::constant(b.number)));
      case '/':
        if (!isNumber(b))
          fail(startOf(e.args[1]),
               "surf divides a polynomial by numbers only; this is a polynomial",
               "multiply through by it, or write the quotient as a polynomial");
        if (b.number == 0) fail(e.place, "division by zero", "the divisor here is 0");
        return polyValue(pa * Poly::constant(1 / b.number));
      case '^': {
        if (b.type != Value::Type::Int || b.number < 0)
          fail(e.args[1].place, "a polynomial's exponent is a whole number from 0 up",
               "write x^2, not x^2.0 or x^-1");
        if (b.number > 256)
          fail(e.args[1].place, "this exponent is too large",
               "zeroset takes exponents up to 256 here");
        if (e.args[0].kind == Expr::Kind::Negate)
          note(e.place,
               "surf reads -x^2 as (-x)^2 (its sign binds tighter than ^), and so does zeroset: "
               "write -(x^2) for minus x squared");
        return polyValue(pa.pow(static_cast<int>(b.number)));
      }
    }
    fail(e.place, "unexpected operator");
  }

  double numberArg(const Expr& call, std::size_t i) {
    const Value v = evaluate(call.args[i]);
    if (!isNumber(v))
      fail(call.args[i].place,
           call.text + " takes a number here; this is " + std::string(typeName(v.type)),
           call.text == "rotate" ? "rotate(POLY, ANGLE, xAxis|yAxis|zAxis)" : "");
    return v.number;
  }

  Value call(const Expr& e) {
    using Fn = double (*)(double);
    static const std::map<std::string, Fn, std::less<>> numeric = {
        {"sqrt", [](double v) { return std::sqrt(v); }},
        {"sin", [](double v) { return std::sin(v); }},
        {"cos", [](double v) { return std::cos(v); }},
        {"tan", [](double v) { return std::tan(v); }},
        {"cot", [](double v) { return std::cos(v) / std::sin(v); }},
        {"arcsin", [](double v) { return std::asin(v); }},
        {"arccos", [](double v) { return std::acos(v); }},
        {"arctan", [](double v) { return std::atan(v); }},
        {"arccot", [](double v) { return M_PI / 2 - std::atan(v); }},
    };
    auto arity = [&](std::size_t n, const char* usage) {
      if (e.args.size() != n)
        fail(e.place,
             e.text + " takes " + std::to_string(n) + " argument" + (n > 1 ? "s" : "") + ", not " +
                 std::to_string(e.args.size()),
             usage);
    };
    if (auto f = numeric.find(e.text); f != numeric.end()) {
      arity(1, (e.text + "(NUMBER)").c_str());
      const Value v = evaluate(e.args[0]);
      if (!isNumber(v))
        fail(e.args[0].place, e.text + " takes a number; this is " + std::string(typeName(v.type)),
             "surf's functions apply to numbers, not to polynomials in x, y, z");
      const double r = f->second(v.number);
      if (!std::isfinite(r))
        fail(e.place, e.text + "(" + shortestText(v.number) + ") is not a number",
             "keep the argument in the function's domain");
      if (e.text == "arcsin" && v.type == Value::Type::Double)
        note(e.place,
             "surf 1.0.6 computes sin, not arcsin, of a number with a decimal point (a bug); "
             "zeroset computes arcsin");
      return doubleValue(r);
    }
    if (e.text == "pow") {
      arity(2, "pow(NUMBER, NUMBER)");
      const double r = std::pow(numberArg(e, 0), numberArg(e, 1));
      if (!std::isfinite(r)) fail(e.place, "pow(...) is not a number here");
      return doubleValue(r);
    }
    if (e.text == "rotate") return rotate(e);
    if (e.text == "deg") {
      arity(1, "deg(POLY)");
      const Value v = evaluate(e.args[0]);
      if (v.type != Value::Type::Poly) return intValue(0);
      return intValue(v.poly->degree());
    }
    if (e.text == "itostr" || e.text == "itostrn") {
      const bool padded = e.text == "itostrn";
      arity(padded ? 2 : 1, padded ? "itostrn(WIDTH, INTEGER)" : "itostr(INTEGER)");
      std::string digits = std::to_string(static_cast<long long>(numberArg(e, padded ? 1 : 0)));
      if (padded) {
        const auto width = static_cast<std::size_t>(std::max(0.0, numberArg(e, 0)));
        if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
      }
      return stringValue(digits);
    }
    for (const char* unsupported :
         {"diff", "hessian_curve", "hessian_surface", "hesse", "len", "itoasc", "itoascn"})
      if (e.text == unsupported)
        fail(e.place, "zeroset does not read surf's " + e.text + "(...) yet",
             "write the polynomial it stands for out in full");
    std::vector<std::string_view> names{"sqrt",   "sin",    "cos",    "tan",    "cot",
                                        "arcsin", "arccos", "arctan", "arccot", "pow",
                                        "rotate", "deg",    "itostr", "itostrn"};
    std::string hint = didYouMean(e.text, names);
    if (hint.empty())
      hint = "surf's functions: sqrt sin cos tan cot arcsin arccos arctan arccot pow rotate";
    fail(e.place, "unknown function '" + e.text + "'", hint);
  }

  // surf's rotate(p, a, axis): p with its coordinates turned (polyarith.cc), e.g. about the
  // x axis p(x, c y + s z, -s y + c z).
  Value rotate(const Expr& e) {
    if (e.args.size() != 3)
      fail(e.place, "rotate takes 3 arguments, not " + std::to_string(e.args.size()),
           "rotate(POLY, ANGLE, xAxis|yAxis|zAxis)");
    const Value p = evaluate(e.args[0]);
    if (p.type == Value::Type::String)
      fail(e.args[0].place, "rotate turns a polynomial; this is a string");
    const double angle = numberArg(e, 1);
    const Expr& axisExpr = e.args[2];
    if (axisExpr.kind != Expr::Kind::Name ||
        (axisExpr.text != "xAxis" && axisExpr.text != "yAxis" && axisExpr.text != "zAxis"))
      fail(axisExpr.place, "the axis is xAxis, yAxis or zAxis",
           "rotate(POLY, ANGLE, xAxis|yAxis|zAxis)");
    const Poly poly = p.type == Value::Type::Poly ? *p.poly : Poly::constant(p.number);
    return polyValue(poly.substitute(surfRotation(angle, axisExpr.text[0] - 'x')));
  }

  Globals globals_;
  std::map<std::string, Value, std::less<>> locals_;
  std::vector<Drawing> screen_;
  ScriptRun out_;
};

}  // namespace

std::variant<ScriptRun, ScriptError> runScript(std::string_view text) {
  auto parsed = parseScript(text);
  if (auto* e = std::get_if<ScriptError>(&parsed)) return *e;
  try {
    return Runner().run(std::get<std::vector<Statement>>(parsed));
  } catch (const Failure& f) {
    return f.error;
  }
}

}  // namespace zs::surfscript
