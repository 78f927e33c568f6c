// libFuzzer target for the .jsurf reader (src/jsurf): any bytes in; the importer must either
// reject them with a SceneError that prints, or give a Scene (with warnings that print)
// that the .surf writer and reader carry unchanged, and that exportJsurf either writes or
// refuses with a reason. Crashes, sanitizer reports and the abort() below are findings.
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "jsurf/jsurf.hpp"
#include "scene/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  zs::jsurf::ImportResult result = zs::jsurf::importJsurf(text, "fuzz.jsurf");
  if (auto* error = std::get_if<zs::SceneError>(&result)) {
    if (error->line < 0 || error->column < 0) std::abort();
    (void)zs::formatSceneError(*error);
    return 0;
  }
  const zs::jsurf::Imported& imported = std::get<zs::jsurf::Imported>(result);
  for (const zs::SceneError& warning : imported.warnings) (void)zs::jsurf::formatWarning(warning);
  zs::SceneResult again = zs::parseScene(zs::saveScene(imported.scene), "imported.surf");
  if (!std::holds_alternative<zs::Scene>(again) || !(std::get<zs::Scene>(again) == imported.scene))
    std::abort();
  auto exported = zs::jsurf::exportJsurf(imported.scene);
  if (auto* refused = std::get_if<std::string>(&exported); refused && refused->empty())
    std::abort();
  return 0;
}
