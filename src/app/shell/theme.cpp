#include "app/shell/theme.hpp"

namespace csl::app::theme {

ImU32 component_color(int component, unsigned alpha) {
  // The largest component is usually 0 (it holds the start): the calm blue; then distinct hues.
  static const ImU32 kCycle[] = {rgba(0, 114, 178),  rgba(0, 158, 115),  rgba(204, 121, 167), rgba(86, 180, 233),
                                 rgba(213, 94, 0),   rgba(120, 94, 240), rgba(0, 0, 0),       rgba(150, 150, 60)};
  const ImU32 c = kCycle[static_cast<unsigned>(component) % (sizeof kCycle / sizeof kCycle[0])];
  return with_alpha(c, alpha);
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
}

}  // namespace csl::app::theme
