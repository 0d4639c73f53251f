#include "app/shell/fonts.hpp"

#include "app/shell/ui_font.hpp"

namespace csl::app {
namespace {
Fonts g_fonts;

ImFont* add(float logical_size, float pixel_ratio) {
  ImFontConfig config;
  config.FontDataOwnedByAtlas = false;  // the data is a constant array in the program
  config.OversampleH = 2;
  config.OversampleV = 1;
  return ImGui::GetIO().Fonts->AddFontFromMemoryTTF(
      const_cast<unsigned char*>(kUiFontData), kUiFontSize, logical_size * pixel_ratio, &config,
      reinterpret_cast<const ImWchar*>(kUiFontRanges));
}
}  // namespace

const Fonts& fonts() { return g_fonts; }

void build_fonts(float pixel_ratio) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  g_fonts.body = add(16.0f, pixel_ratio);
  g_fonts.small = add(13.0f, pixel_ratio);
  g_fonts.title = add(21.0f, pixel_ratio);
  io.Fonts->Build();
  io.FontDefault = g_fonts.body;
  io.FontGlobalScale = 1.0f / pixel_ratio;
}

}  // namespace csl::app
