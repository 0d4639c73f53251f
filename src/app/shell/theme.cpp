#include "app/shell/theme.hpp"

#include <cmath>

namespace csl::app::theme {

ImU32 component_color(int component, unsigned alpha) {
  const ImU32 c = kComponents[static_cast<unsigned>(component) % kComponentCount];
  return with_alpha(c, alpha);
}

ImU32 text_on(ImU32 fill) {
  // WCAG relative luminance; black on it reads better than white above L = 0.179.
  const auto lin = [](unsigned v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const double l = 0.2126 * lin(fill & 0xFF) + 0.7152 * lin((fill >> 8) & 0xFF) + 0.0722 * lin((fill >> 16) & 0xFF);
  return l > 0.179 ? kBlack : rgba(255, 255, 255);
}

void apply_style() {
  ImGui::StyleColorsLight();
  ImGuiStyle& s = ImGui::GetStyle();
  s.WindowRounding = 0.0f;
  s.ChildRounding = 4.0f;
  s.FrameRounding = 4.0f;
  s.GrabRounding = 4.0f;
  s.PopupRounding = 4.0f;
  s.WindowPadding = ImVec2(12, 12);
  s.FramePadding = ImVec2(8, 5);
  s.ItemSpacing = ImVec2(8, 7);
  s.WindowBorderSize = 0.0f;
  s.ScrollbarSize = 12.0f;
  ImVec4* c = s.Colors;
  c[ImGuiCol_WindowBg] = ImVec4(0.96f, 0.96f, 0.95f, 1.0f);
  c[ImGuiCol_ChildBg] = ImVec4(0, 0, 0, 0);
  c[ImGuiCol_Button] = ImVec4(0.0f, 0.447f, 0.698f, 0.16f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.0f, 0.447f, 0.698f, 0.32f);
  c[ImGuiCol_ButtonActive] = ImVec4(0.0f, 0.447f, 0.698f, 0.48f);
  c[ImGuiCol_Header] = ImVec4(0.0f, 0.447f, 0.698f, 0.16f);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.0f, 0.447f, 0.698f, 0.28f);
  c[ImGuiCol_HeaderActive] = ImVec4(0.0f, 0.447f, 0.698f, 0.40f);
  c[ImGuiCol_Text] = ImVec4(0.10f, 0.10f, 0.12f, 1.0f);
  // ImGui's light grey (0.6) is 2.6:1 on the panel; secondary text must read too (4.5:1).
  c[ImGuiCol_TextDisabled] = vec4(kTextDim);
}

}  // namespace csl::app::theme
