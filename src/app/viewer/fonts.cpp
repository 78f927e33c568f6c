#include "app/viewer/fonts.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace zs::app {
namespace {

ImFont* g_formulaFont = nullptr;  // in the ImGui context's atlas, which owns it

}  // namespace

ImFont* formulaFont() {
  return g_formulaFont ? g_formulaFont : ImGui::GetFont();
}

std::string findViewerFont() {
  if (const char* own = std::getenv("ZS_FONT"); own && *own) return own;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                           "/usr/local/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                           "/usr/share/fonts/dejavu/DejaVuSans.ttf"}) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  return {};
}

std::string loadViewerFont(float contentScale) {
  g_formulaFont = nullptr;  // of an earlier ImGui context, if any
  const float scale = std::clamp(contentScale, 0.5f, 4.0f);
  const std::string path = findViewerFont();
  if (path.empty()) {
    return "DejaVu Sans not found (Debian package fonts-dejavu-core); the panel uses "
           "ImGui's built-in font, which lacks symbols such as \u2014 and \u00b2";
  }
  // Basic Latin and Latin-1 (which has ² and ³), Latin Extended-A, Greek, general
  // punctuation (— – …), super- and subscripts, letterlike symbols, arrows, math operators.
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0100, 0x017F, 0x0370, 0x03FF,
                                    0x2000, 0x206F, 0x2070, 0x209F, 0x2100, 0x214F,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  ImGuiIO& io = ImGui::GetIO();
  ImFontConfig config;
  config.OversampleH = 2;
  ImFont* font =
      io.Fonts->AddFontFromFileTTF(path.c_str(), kViewerFontSize * scale, &config, kRanges);
  if (!font) return "could not read the font " + path + "; the panel uses ImGui's built-in font";
  io.FontDefault = font;
  // Its monospaced sibling, where the family is installed whole.
  const std::filesystem::path mono =
      std::filesystem::path(path).parent_path() / "DejaVuSansMono.ttf";
  std::error_code ec;
  g_formulaFont =
      std::filesystem::is_regular_file(mono, ec)
          ? io.Fonts->AddFontFromFileTTF(mono.c_str(), kViewerFontSize * scale, &config, kRanges)
          : nullptr;
  ImGui::GetStyle().ScaleAllSizes(scale);
  return {};
}

}  // namespace zs::app
