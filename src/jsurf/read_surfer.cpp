#include "jsurf/read_surfer.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "jsurf/properties.hpp"
#include "jsurf/value_reader.hpp"
#include "parser/parser.hpp"
#include "parser/suggest.hpp"

namespace zs::jsurf {
namespace {

constexpr std::string_view kParamPrefix = "surface_parameter_";
constexpr std::array<std::string_view, 4> kLightFields{"status", "position", "color", "intensity"};
constexpr std::array<std::string_view, 5> kMaterialFields{
    "color", "ambient_intensity", "diffuse_intensity", "specular_intensity", "shininess"};

// The known key nearest an unknown one (the parser's suggestion rule), or "".
std::string closestKey(std::string_view key) {
  const std::vector<std::string>& keys = surferKeys();
  return closestName(key, std::vector<std::string_view>(keys.begin(), keys.end()), 3).value_or("");
}

// Reads the properties into SurferScene, one key at a time.
class Reader {
 public:
  Reader(std::string_view text, std::string_view fileName) : values_(text, fileName) {}

  std::variant<SurferRead, SceneError> run(const std::vector<Property>& props) {
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < props.size(); ++i) {
      const Property& p = props[i];
      if (auto [it, fresh] = seen.emplace(p.key, i); !fresh) {
        out_.warnings.push_back(values_.atKey(
            p, "key " + p.key + " appears again; this later value counts, as in SURFER"));
        it->second = i;
      }
    }
    bool cameraTransformGiven = false;
    bool hasFormula = false;
    Mat4 transform = identity4();
    Mat4 rotation = identity4();
    for (const Property& p : props) {
      if (seen.at(p.key) != static_cast<std::size_t>(&p - props.data())) continue;
      if (!error_) {
        if (p.key == "surface_equation")
          hasFormula = formula(p);
        else if (p.key.starts_with(kParamPrefix))
          param(p);
        else if (p.key == "camera_transform")
          cameraTransformGiven = matrix(p, out_.scene.view.cameraTransform);
        else if (p.key == "rotation_matrix")
          matrix(p, rotation);
        else if (p.key == "transform_matrix")
          matrix(p, transform);
        else
          other(p);
      }
    }
    if (error_) return *error_;
    if (!hasFormula)
      return values_.nowhere("surface_equation",
                             "no surface_equation: a .jsurf file needs the formula",
                             "add a line such as surface_equation=x^2+y^2+z^2-1");
    SurferView& view = out_.scene.view;
    view.rotation = multiply(transform, rotation);
    if (!cameraTransformGiven)
      view.cameraTransform = surferDefaultCameraTransform(view.orthographic, view.fovY);
    std::sort(out_.scene.params.begin(), out_.scene.params.end());
    return std::move(out_);
  }

 private:
  void fail(SceneError e) {
    if (!error_) error_ = std::move(e);
  }
  void warn(SceneError e) { out_.warnings.push_back(std::move(e)); }

  bool formula(const Property& p) {
    const ParseResult parsed = parseFormula(p.value);
    if (const auto* err = std::get_if<ParseError>(&parsed)) {
      const int width = static_cast<int>(std::max<std::size_t>(1, err->span.end - err->span.begin));
      fail(values_.at(p, err->span.begin, "surface_equation: " + err->message, err->hint, width));
      return false;
    }
    out_.scene.formula = p.value;
    return true;
  }

  void param(const Property& p) {
    const std::string name = p.key.substr(kParamPrefix.size());
    const ParseResult parsed = parseFormula(name);
    const auto* f = std::get_if<Formula>(&parsed);
    if (!f || f->graph.params().size() != 1 || f->graph.params()[0] != name) {
      warn(values_.atKey(p, "'" + name + "' is not a parameter name in zeroset; the key is ignored",
                         name == "e" || name == "pi"
                             ? "zeroset reads " + name + " as the constant, not as a parameter"
                             : "parameters are names such as a, b, c, d (docs/formula.md)"));
      return;
    }
    SceneError e;
    if (auto v = values_.number(p, e))
      out_.scene.params.emplace_back(name, *v);
    else
      fail(std::move(e));
  }

  bool matrix(const Property& p, Mat4& m) {
    SceneError e;
    auto n = values_.numbers(p, 16, e);
    if (!n) {
      fail(std::move(e));
      return false;
    }
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = (*n)[static_cast<std::size_t>(4 * r + c)];
    Mat4 inverse;
    if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1) {
      fail(values_.at(p, 0, p.key + " must be affine: its last row must be 0 0 0 1",
                      "SURFER does not support projective transformations either"));
      return false;
    }
    if (!invertAffine(m, inverse)) {
      fail(values_.at(p, 0, p.key + " cannot be inverted",
                      "a rotation or camera placement is invertible"));
      return false;
    }
    return true;
  }

  std::optional<double> number(const Property& p) {
    SceneError e;
    auto v = values_.number(p, e);
    if (!v) fail(std::move(e));
    return v;
  }

  std::optional<Vec3> vec3(const Property& p) {
    SceneError e;
    auto n = values_.numbers(p, 3, e);
    if (!n) {
      fail(std::move(e));
      return std::nullopt;
    }
    return Vec3{(*n)[0], (*n)[1], (*n)[2]};
  }

  void color(const Property& p, Vec3& out) {
    auto c = vec3(p);
    if (!c) return;
    for (double& x : *c) {
      if (x < 0 || x > 1) {
        warn(values_.at(p, 0, p.key + ": colour components lie in [0, 1]; clamped"));
        x = std::clamp(x, 0.0, 1.0);
      }
    }
    out = *c;
  }

  // A number >= 0 (intensities, shininess).
  void nonNegative(const Property& p, double& out) {
    auto v = number(p);
    if (!v) return;
    if (*v < 0) {
      warn(values_.at(p, 0, p.key + " must not be negative; taken as 0"));
      *v = 0;
    }
    out = *v;
  }

  void word(const Property& p, std::string_view a, std::string_view b, bool& isA) {
    if (p.value == a || p.value == b) {
      isA = p.value == a;
      return;
    }
    fail(values_.at(
        p, 0,
        p.key + " is '" + p.value + "'; SURFER knows " + std::string(a) + " and " + std::string(b),
        "write " + std::string(a) + " or " + std::string(b) + " in capitals",
        static_cast<int>(std::max<std::size_t>(1, p.value.size()))));
  }

  bool light(const Property& p) {
    if (!p.key.starts_with("light_")) return false;
    for (std::string_view field : kLightFields) {
      const std::string prefix = "light_" + std::string(field) + "_";
      if (!p.key.starts_with(prefix) || p.key.size() != prefix.size() + 1) continue;
      const char digit = p.key.back();
      if (digit < '0' || digit >= '0' + kSurferLights) return false;
      SurferLight& l = out_.scene.lights[static_cast<std::size_t>(digit - '0')];
      if (field == "status")
        word(p, "ON", "OFF", l.on);
      else if (field == "position") {
        if (auto v = vec3(p)) l.position = *v;
      } else if (field == "color")
        color(p, l.color);
      else
        nonNegative(p, l.intensity);
      return true;
    }
    return false;
  }

  bool material(const Property& p) {
    for (const bool front : {true, false}) {
      const std::string prefix = front ? "front_material_" : "back_material_";
      if (!p.key.starts_with(prefix)) continue;
      SurferMaterial& m = front ? out_.scene.front : out_.scene.back;
      const std::string field = p.key.substr(prefix.size());
      if (field == "color")
        color(p, m.color);
      else if (field == "ambient_intensity")
        nonNegative(p, m.ambient);
      else if (field == "diffuse_intensity")
        nonNegative(p, m.diffuse);
      else if (field == "specular_intensity")
        nonNegative(p, m.specular);
      else if (field == "shininess")
        nonNegative(p, m.shininess);
      else
        return false;
      return true;
    }
    return false;
  }

  void other(const Property& p) {
    SurferView& view = out_.scene.view;
    if (p.key == "scale_factor") {
      if (auto v = number(p)) view.scaleFactor = *v;
      if (std::abs(view.scaleFactor) > 100)
        fail(values_.at(p, 0, "scale_factor is the zoom's log10; |scale_factor| <= 100"));
    } else if (p.key == "camera_type") {
      word(p, "ORTHOGRAPHIC_CAMERA", "PERSPECTIVE_CAMERA", view.orthographic);
    } else if (p.key == "camera_fov_y") {
      auto v = number(p);
      if (v && (*v <= 0 || *v >= 180))
        fail(values_.at(p, 0, "camera_fov_y must lie in (0, 180) degrees"));
      else if (v)
        view.fovY = *v;
    } else if (p.key == "camera_height") {
      auto v = number(p);
      if (v && *v <= 0)
        fail(values_.at(p, 0, "camera_height must be above 0"));
      else if (v)
        view.height = *v;
    } else if (p.key == "background_color") {
      color(p, out_.scene.background);
    } else if (p.key == "surface_transform_matrix") {
      warn(values_.atKey(
          p, "surface_transform_matrix is not supported (SURFER ignores it too); ignored"));
    } else if (!light(p) && !material(p)) {
      const std::string near = closestKey(p.key);
      warn(values_.atKey(p, "unknown key " + p.key + "; ignored (SURFER ignores it too)",
                         near.empty() ? "" : "did you mean " + near + "?"));
    }
  }

  ValueReader values_;
  SurferRead out_;
  std::optional<SceneError> error_;
};

}  // namespace

const std::vector<std::string>& surferKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k{"surface_equation", "scale_factor",     "rotation_matrix",
                               "transform_matrix", "camera_type",      "camera_fov_y",
                               "camera_height",    "camera_transform", "background_color"};
    for (const char* side : {"front_material_", "back_material_"})
      for (std::string_view f : kMaterialFields) k.push_back(side + std::string(f));
    for (int i = 0; i < kSurferLights; ++i)
      for (std::string_view f : kLightFields)
        k.push_back("light_" + std::string(f) + "_" + std::to_string(i));
    return k;
  }();
  return keys;
}

std::variant<SurferRead, SceneError> readSurferScene(std::string_view text,
                                                     std::string_view fileName) {
  return Reader(text, fileName).run(readProperties(text));
}

}  // namespace zs::jsurf
