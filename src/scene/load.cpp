// The entry points that read whole scenes: a .surf text, a file, or a bare formula.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <numeric>
#include <sstream>

#include "parser/parser.hpp"
#include "scene/reader.hpp"
#include "scene/scene_io.hpp"
#include "scene/schema.hpp"

namespace zs {

namespace {

using namespace scene_detail;

// Far beyond any hand-written scene; stops a mistaken path (a video, /dev/zero) early.
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;

SceneError fileError(const std::filesystem::path& path, std::string message) {
  SceneError e;
  e.file = path.string();
  e.message = std::move(message);
  return e;
}

}  // namespace

SceneResult parseScene(std::string_view text, std::string_view fileName) {
  const SourceText src(fileName, text);
  Scene scene;
  try {
    const toml::table doc = toml::parse(text, fileName);
    if (auto err = applyDocument(scene, doc, src)) return *err;
    // [[surface]] tables carry their formulas; [surface] (the level) does not.
    const toml::node* surfaces = doc.get(kSurfacesKey);
    if (!doc.contains(kFormulaKey) && !(surfaces && surfaces->is_array())) {
      return src.error({1, 1}, "formula", "the scene has no formula",
                       "add formula = \"...\" before the first [table], e.g. "
                       "formula = \"x^2 + y^2 + z^2 - 1\"");
    }
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    return src.error({static_cast<int>(at.line), static_cast<int>(at.column)}, "",
                     std::string(e.description()));
  } catch (const std::exception& e) {
    return fileError(std::string(fileName), std::string("cannot read the scene: ") + e.what());
  }
  return scene;
}

std::variant<std::string, SceneError> readSceneFile(const std::filesystem::path& path,
                                                    std::string_view what) {
  const std::string kind(what);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return fileError(path, "is a directory, not a " + kind);
  std::ifstream in(path, std::ios::binary);
  if (!in) return fileError(path, "cannot open " + kind + ": " + std::strerror(errno));
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxSceneBytes) {
    return fileError(path,
                     kind + " is larger than " + std::to_string(kMaxSceneBytes >> 20) + " MiB");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return fileError(path, "cannot read " + kind + ": " + std::strerror(errno));
  return text.str();
}

SceneResult loadScene(const std::filesystem::path& path) {
  auto text = readSceneFile(path, "scene file");
  if (auto* err = std::get_if<SceneError>(&text)) return *err;
  return parseScene(std::get<std::string>(text), path.string());
}

std::optional<SceneError> checkImportedScene(const Scene& scene, std::string_view fileName,
                                             std::string_view importer) {
  const SceneResult check = parseScene(saveScene(scene), fileName);
  const auto* err = std::get_if<SceneError>(&check);
  if (!err) return std::nullopt;
  SceneError e = *err;
  e.line = 0;
  e.message = "the imported scene is not valid (a bug in zeroset's " + std::string(importer) +
              " import): " + e.message;
  return e;
}

SceneResult loadSceneOrFormula(std::string_view arg) {
  std::error_code ec;  // a long formula is no valid path: exists() then fails quietly
  if (arg.ends_with(".surf") || std::filesystem::exists(std::filesystem::path(arg), ec)) {
    return loadScene(std::filesystem::path(arg));
  }
  const SourceText src("<formula>", arg);
  std::vector<std::size_t> identity(arg.size() + 1);
  std::iota(identity.begin(), identity.end(), std::size_t{0});
  if (auto err = checkFormula(arg, src, identity)) return *err;
  Scene scene;
  scene.formula = std::string(arg);
  return scene;
}

std::vector<double> paramValues(const Scene& scene, const Graph& graph) {
  std::vector<double> values;
  values.reserve(graph.params().size());
  for (const std::string& name : graph.params()) {
    double v = kDefaultParamValue;
    for (const auto& [sceneName, sceneValue] : scene.params) {
      if (sceneName == name) v = sceneValue;
    }
    values.push_back(v);
  }
  return values;
}

std::vector<std::string> sceneKeys() {
  std::vector<std::string> keys{std::string(kFormulaKey)};
  for (const KeySpec& k : keySpecs()) keys.emplace_back(k.name);
  return keys;
}

}  // namespace zs
