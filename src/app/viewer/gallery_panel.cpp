#include "app/viewer/gallery_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdint>

#include "i18n/translate.hpp"

namespace zs::app {

int drawGallery(GalleryPanel& g, int current) {
  int picked = -1;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Top right, beside the panel, leaving most of the surface in view.
  ImGui::SetNextWindowPos(ImVec2(std::max(8.0f, display.x - 348), 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(
      ImVec2(340, std::max(120.0f, std::min(display.y - 16, display.y * 0.6f))),
      ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin(i18n::label("gallery"), &g.visible)) {
    g.searchFocus.beforeItem();
    ImGui::SetNextItemWidth(-1);
    const bool enter = ImGui::InputTextWithHint("##search", i18n::tr("search: name or description"),
                                                &g.search, ImGuiInputTextFlags_EnterReturnsTrue);
    g.searchFocus.afterItem();
    int firstMatch = -1;
    ImGui::BeginChild("entries");
    for (std::size_t i = 0; i < g.entries.size(); ++i) {
      const GalleryEntry& e = g.entries[i];
      if (!g.search.empty() && !galleryMatches(e, g.search)) continue;
      if (firstMatch < 0) firstMatch = static_cast<int>(i);
      ImGui::PushID(static_cast<int>(i));
      float aspect = 1;
      if (const std::uint32_t tex =
              e.picture.empty() ? 0 : g.thumbnails.texture(e.picture, aspect)) {
        constexpr float kHeight = 48;
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(tex)),
                     ImVec2(kHeight * aspect, kHeight));
        ImGui::SameLine();
      }
      ImGui::BeginGroup();
      const std::string label = std::string(i18n::tr(e.name.c_str())) + "   " +
                                i18n::format(i18n::tr("degree %s"), e.degree.c_str());
      if (ImGui::Selectable(label.c_str(), static_cast<int>(i) == current))
        picked = static_cast<int>(i);
      if (ImGui::IsItemHovered() && !e.description.empty()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30);
        ImGui::TextUnformatted(e.description.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
      ImGui::PushTextWrapPos(0);
      ImGui::TextDisabled(
          "%s", e.summary.empty() ? i18n::tr("(no description)") : i18n::tr(e.summary.c_str()));
      ImGui::PopTextWrapPos();
      ImGui::EndGroup();
      ImGui::PopID();
    }
    if (firstMatch < 0) ImGui::TextDisabled("%s", i18n::tr("no example matches"));
    ImGui::EndChild();
    if (enter && firstMatch >= 0) picked = firstMatch;
    // Give the keyboard back to the viewer, so N/P go on from the pick.
    if (picked >= 0) ImGui::SetWindowFocus(nullptr);
  }
  ImGui::End();
  return picked;
}

}  // namespace zs::app
