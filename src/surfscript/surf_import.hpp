#pragma once
// surf's scripts as zeroset scenes and pictures (docs/surf.md). importSurfScript gives the
// scene of the script's last surface drawing, for `zeroset render/view/import/mesh/print
// FILE.pic`; runSurfScript gives every picture the script saves, for the `surf` command.
// Errors and notes carry file:line:column; nothing here throws.
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "curve/curve.hpp"
#include "scene/scene_io.hpp"
#include "surfscript/script_run.hpp"

namespace zs::surfscript {

// A draw_curve on a picture: the curve f(x, y) = 0 (zeroset's formula text) in the
// picture's pixels, surf's curve_width and colour; where surf clips to its sphere, the disc
// of the picture it keeps.
struct ScriptCurve {
  std::string formula;
  curve::PixelMap map;
  double halfWidth = 1.5;  // pixels
  Vec3 color{1, 1, 1};
  bool clipped = false;  // keep only pixels within the disc below (screen units)
  double discU = 0, discV = 0, discRadius = 10;
  double u0 = -10, du = 0.1, v0 = 10, dv = -0.1;  // pixel centre -> surf's screen point
};

// One save_color_image: the file, its format, and the last drawing before it, as surf
// keeps only that: the scene of a draw_surface, or for a draw_curve an empty formula (a
// black picture) with the curve drawn on it.
struct ScriptPicture {
  std::string fileName;
  ImageFormat format = ImageFormat::Sun;
  Scene scene;
  std::vector<ScriptCurve> curves;
  SceneError place;  // where the script saves it (file, line, column), for messages
};

struct ScriptPictures {
  std::vector<ScriptPicture> pictures;
  std::vector<SceneError> warnings;
};

ImportResult importSurfScript(std::string_view text, std::string_view fileName);
ImportResult loadSurfScript(const std::filesystem::path& path);

std::variant<ScriptPictures, SceneError> runSurfScript(std::string_view text,
                                                       std::string_view fileName);

// True for a name ending in ".pic" (any case): surf's scripts as SURFER-2008 keeps them.
bool isSurfScriptPath(std::string_view path);

}  // namespace zs::surfscript
