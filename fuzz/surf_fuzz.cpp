// libFuzzer target for the .surf reader (src/scene): any bytes in; the reader must either
// reject them with a SceneError whose line and column lie inside the text, printable with
// its caret, or give a Scene that saveScene writes and parseScene reads back equal (the
// round trip scene_io.hpp promises). Crashes, sanitizer reports and the abort() below are
// findings.
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "scene/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  zs::SceneResult result = zs::parseScene(text, "fuzz.surf");
  if (auto* error = std::get_if<zs::SceneError>(&result)) {
    if (error->line < 0 || error->column < 0 || error->width < 0) std::abort();
    (void)zs::formatSceneError(*error);
    return 0;
  }
  const zs::Scene& scene = std::get<zs::Scene>(result);
  zs::SceneResult again = zs::parseScene(zs::saveScene(scene), "saved.surf");
  if (!std::holds_alternative<zs::Scene>(again) || !(std::get<zs::Scene>(again) == scene))
    std::abort();
  return 0;
}
