// applyOverride: `--set KEY=VALUE` is itself one line of TOML, so it is parsed as a tiny
// document and goes through the same reader as a file; columns then point into the
// assignment exactly as the user typed it.
#include <span>
#include <string>
#include <vector>

#include "scene/reader.hpp"
#include "scene/scene_io.hpp"

namespace zs {

namespace {

using namespace scene_detail;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// What a TOML value can start with; anything else is most likely text missing its quotes.
bool looksLikeTomlValue(std::string_view v) {
  if (v.empty()) return false;
  if (std::string_view("\"'[{+-.0123456789").find(v[0]) != std::string_view::npos) return true;
  return v.starts_with("true") || v.starts_with("false") || v.starts_with("inf") ||
         v.starts_with("nan");
}

constexpr const char* kQuoteHint =
    "VALUE is a TOML value; text needs double quotes, e.g. --set 'formula=\"x^2 + y^2 - 1\"' "
    "or --set 'camera.projection=\"orthographic\"'";

// One assignment onto `scene`, its keys appended to `history`; the cross-key check is the
// caller's (applyOverrides runs it once, after the last assignment).
std::optional<SceneError> applyOne(Scene& scene, const SourceText& src, KeyHistory& history) {
  const std::string_view assignment = src.text();
  if (const auto nl = assignment.find_first_of("\r\n"); nl != std::string_view::npos) {
    return src.error(src.positionOf(nl), "", "a --set assignment must be a single line");
  }
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    return src.error(src.positionOf(assignment.size()), "",
                     "expected KEY=VALUE, got \"" + std::string(assignment) + "\"",
                     "for example --set camera.eye=[0,0,3] or --set params.a=0.2");
  }
  const std::string key(trim(assignment.substr(0, eq)));
  if (key.empty())
    return src.error({1, 1}, "", "missing KEY before '='", "for example --set octree.level=3");
  const std::string_view value = trim(assignment.substr(eq + 1));
  if (value.empty()) {
    return src.error(src.positionOf(eq + 1), key, "missing VALUE after '" + key + "='",
                     "VALUE is a TOML value: 0.2, [0, 0, 3], true, \"text\"");
  }
  try {
    const toml::table doc = toml::parse(assignment, std::string_view("--set"));
    return applyDocument(scene, doc, src, &history);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    return src.error({static_cast<int>(at.line), static_cast<int>(at.column)}, key,
                     std::string(e.description()), looksLikeTomlValue(value) ? "" : kQuoteHint);
  } catch (const std::exception& e) {
    return src.error({1, 1}, key, std::string("cannot apply the assignment: ") + e.what());
  }
}

}  // namespace

std::optional<SceneError> applyOverrides(Scene& scene, std::span<const std::string> assignments) {
  if (assignments.empty()) return std::nullopt;
  std::vector<SourceText> sources;  // the history points into these
  sources.reserve(assignments.size());
  KeyHistory history;
  Scene changed = scene;
  for (const std::string& assignment : assignments) {
    sources.emplace_back("--set", assignment);
    if (auto err = applyOne(changed, sources.back(), history)) return err;
  }
  // Keys that constrain each other are checked once all are set: --set camera.up=[0,0,1]
  // --set camera.eye=[0,0,5] is fine in either order.
  if (auto err = crossCheck(changed, history, sources.back())) return err;
  scene = std::move(changed);
  return std::nullopt;
}

std::optional<SceneError> applyOverride(Scene& scene, std::string_view assignment) {
  const std::string one(assignment);
  return applyOverrides(scene, std::span<const std::string>(&one, 1));
}

}  // namespace zs
