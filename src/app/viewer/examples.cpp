// Example discovery. $ZS_SOURCE_DIR (which the test suite sets) points any binary at a
// checkout; otherwise the gallery is found relative to the executable, where it is
// installed (PREFIX/bin/zeroset finds PREFIX/share/zeroset/examples, so an installed tree
// may be moved). The build tree mirrors that layout with a link (src/app/CMakeLists.txt),
// so no path into the source tree is compiled in.
#include "app/viewer/examples.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <system_error>
#include <variant>

#include "i18n/translate.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {
namespace fs = std::filesystem;

namespace {

struct BuiltIn {
  const char* name;
  const char* formula;
};

// Thesis Table 5.1, in its order and with its names.
constexpr std::array<BuiltIn, 7> kThesisSurfaces{{
    {N_("1 cross channel"), "x^2 + z^2 - y"},
    {N_("2 Cayley cubic"),
     "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)"},
    {N_("3 cuboid"), "x^4 + y^4 + z^4 - 1"},
    {N_("4 peninsula"), "x^2 + y^3 + z^5 - 1"},
    {N_("5 Klein quartic"), "x^3*y + y^3*z + z^3*x"},
    {N_("6 quartic saddle"), "x^4 - z^4 - y"},
    {N_("7 fitting surface"), "x^2*y^2 + y^2*z^2 + z^2*x^2 - 1"},
}};

bool isDir(const fs::path& p) {
  std::error_code ec;
  return !p.empty() && fs::is_directory(p, ec);
}

fs::path executableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : exe.parent_path();
}

std::vector<fs::path> surfFiles(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  if (!isDir(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.is_regular_file(ec) && entry.path().extension() == ".surf")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

fs::path findExamplesDir() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("ZS_SOURCE_DIR"); env && *env)
    candidates.push_back(fs::path(env) / "examples");
  if (fs::path exe = executableDir(); !exe.empty()) {
    candidates.push_back(exe / ".." / "share" / "zeroset" / "examples");
    candidates.push_back(exe / ".." / "examples");
    candidates.push_back(exe / ".." / ".." / "examples");
  }
  for (const fs::path& dir : candidates) {
    if (isDir(dir)) return dir;
  }
  return {};
}

std::vector<Example> listExamples(const fs::path& examplesDir) {
  std::vector<Example> examples;
  for (const fs::path& dir : {examplesDir / "thesis", examplesDir}) {
    if (examplesDir.empty()) break;
    for (const fs::path& file : surfFiles(dir)) {
      const std::string prefix = dir == examplesDir ? "" : "thesis/";
      examples.push_back({prefix + file.stem().string(), file, {}});
    }
  }
  if (examples.empty()) {
    for (const BuiltIn& b : kThesisSurfaces) examples.push_back({b.name, {}, b.formula});
  }
  return examples;
}

std::variant<Scene, std::string> loadExample(const Example& example) {
  if (!example.file.empty()) {
    SceneResult loaded = loadScene(example.file);
    if (auto* err = std::get_if<SceneError>(&loaded)) return formatSceneError(*err);
    return std::get<Scene>(std::move(loaded));
  }
  Scene scene;
  scene.formula = example.formula;
  scene.octree.level = 1;
  scene.render.tracing.intervals = 10;
  scene.render.tracing.epsilon = 0.01;
  return scene;
}

std::string exampleLabel(int index, int count, const std::string& name) {
  return i18n::format(i18n::tr("%d of %d: %s"), index + 1, count, i18n::tr(name.c_str()));
}

}  // namespace zs::app
