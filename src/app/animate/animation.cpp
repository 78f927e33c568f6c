#include "app/animate/animation.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <variant>

#include "parser/parser.hpp"
#include "scene/invalidation.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

namespace {

const char* const kHowTo =
    "hint: write KEY=FROM:TO with KEY params.NAME, surface.level, camera.orbit (degrees) or "
    "another number of the scene as --set names it, e.g. --animate params.a=0:1, "
    "--animate camera.orbit=0:360 or --animate clip.plane.1.offset=-1:1\n";

// The whole of `text` as a finite number.
std::optional<double> number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

double Animation::valueAt(int i) const {
  if (frames <= 1) return from;
  return from + (to - from) * double(i) / double(frames - 1);
}

std::optional<Animation> parseAnimation(const std::string& text, int frames, std::string& error) {
  const std::size_t eq = text.find('=');
  const std::size_t colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || colon == std::string::npos) {
    error = "error: --animate '" + text + "' is not KEY=FROM:TO\n" + kHowTo;
    return std::nullopt;
  }
  Animation anim;
  anim.frames = frames;
  const std::string key = text.substr(0, eq);
  const auto from = number(text.substr(eq + 1, colon - eq - 1));
  const auto to = number(text.substr(colon + 1));
  if (!from || !to) {
    error = "error: --animate '" + text + "': FROM and TO must be finite numbers\n" + kHowTo;
    return std::nullopt;
  }
  anim.from = *from;
  anim.to = *to;
  if (key == "camera.orbit") {
    anim.kind = Animation::Kind::Orbit;
  } else if (key == "surface.level") {
    anim.kind = Animation::Kind::Level;
  } else if (key.rfind("params.", 0) == 0 && key.size() > 7) {
    anim.param = key.substr(7);
  } else if (!key.empty() && key.rfind("params.", 0) != 0 && key.back() != '.' &&
             key.front() != '.') {
    anim.kind = Animation::Kind::Setting;
    anim.param = key;
  } else {
    error = "error: --animate cannot animate '" + key + "'\n" + kHowTo;
    return std::nullopt;
  }
  return anim;
}

Vec3 orbitEye(const Camera& camera, double degrees) {
  // Rodrigues' rotation of (eye - target) about the unit up axis.
  Vec3 k = camera.up;
  const double len = std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  for (double& c : k) c /= len;
  const Vec3 v{camera.eye[0] - camera.target[0], camera.eye[1] - camera.target[1],
               camera.eye[2] - camera.target[2]};
  const double a = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  const Vec3 kxv{k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
  Vec3 eye;
  for (int i = 0; i < 3; ++i)
    eye[i] = camera.target[i] + v[i] * c + kxv[i] * s + k[i] * kv * (1 - c);
  return eye;
}

std::string frameScene(const Animation& anim, const Scene& base, int i, Scene& out) {
  out = base;
  const double value = anim.valueAt(i);
  if (anim.kind == Animation::Kind::Orbit) {
    out.render.camera.eye = orbitEye(base.render.camera, value);
    return {};
  }
  // Through the --set path, so a name the scene format refuses is refused the same way.
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  if (auto err = applyOverride(out, anim.key() + "=" + text)) {
    std::string message = formatSceneError(*err);
    if (anim.kind == Animation::Kind::Setting) message += kHowTo;
    return message;
  }
  return {};
}

bool rebuildsEachFrame(const Animation& anim, const Scene& base) {
  if (anim.frames < 2 || anim.from == anim.to) return false;
  Scene first, last;
  if (!frameScene(anim, base, 0, first).empty() ||
      !frameScene(anim, base, anim.frames - 1, last).empty())
    return true;  // cannot tell; rebuilding is always right
  ParseResult parsed = parseSceneFormula(base);
  const Formula* f = std::get_if<Formula>(&parsed);
  const Invalidation what = invalidation(first, last, f ? &f->graph.params() : nullptr);
  return (what & (invalidates::Shader | invalidates::Geometry)) != 0;
}

}  // namespace zs::app
