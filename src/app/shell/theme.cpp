#include "app/shell/theme.hpp"

#include <cmath>

namespace csl::app::theme {

namespace {

// Light: the lab's first look. Text colours are 4.5:1 on the panel (245, 245, 242).
constexpr Palette kLight = {
    /*canvas_bg*/ rgba(255, 255, 255), /*grid_minor*/ rgba(232, 232, 232), /*grid_major*/ rgba(200, 200, 200),
    /*frame*/ rgba(90, 90, 90), /*obstacle_fill*/ rgba(96, 96, 104, 200), /*obstacle_edge*/ rgba(40, 40, 48),
    /*cobstacle*/ rgba(96, 96, 104, 210),
    /*start*/ kGreen, /*goal*/ kVermillion, /*preview*/ kBlue, /*label*/ rgba(70, 70, 70),
    /*selected_fill*/ rgba(0, 114, 178, 110), /*selected_edge*/ rgba(0, 114, 178), /*warning*/ kVermillion,
    /*free*/ kGreen, /*hit*/ kVermillion, /*path*/ kOrange, /*path_outline*/ rgba(60, 40, 0),
    /*robot*/ kBlue, /*current*/ kPurple,
    /*ink*/ rgba(40, 40, 48), /*faint*/ rgba(120, 120, 120), /*label_box*/ rgba(255, 255, 255, 225),
    /*text_good*/ rgba(0, 115, 77), /*text_bad*/ rgba(179, 64, 0), /*text_key*/ rgba(0, 77, 140),
    /*text_amount*/ rgba(140, 92, 0), /*text_log*/ rgba(0, 89, 153), /*text_notice*/ rgba(153, 51, 0),
    /*text_dim*/ rgba(97, 97, 97), /*restore_button*/ rgba(250, 219, 140),
    /*card_welcome*/ rgba(232, 242, 255), /*card_problem*/ rgba(248, 245, 234),
    // Okabe–Ito's sky blue, a violet and an olive in these places came within 6 to 8 of a neighbour.
    /*components*/ {rgba(0, 114, 178), rgba(0, 158, 115), rgba(204, 121, 167), rgba(51, 34, 136), rgba(213, 94, 0),
                    rgba(120, 60, 0), rgba(0, 0, 0), rgba(170, 51, 119)},
};

// Dark: canvas (22, 24, 28), panel (32, 34, 38). The data hues are lighter so that marks keep
// 3:1 on the canvas; the components were chosen by search for the same CIEDE2000 10 under every
// dichromacy (tests/e2e/colour.test.mjs checks them).
constexpr Palette kDark = {
    rgba(22, 24, 28), rgba(40, 43, 49), rgba(66, 70, 78),
    rgba(150, 150, 156), rgba(128, 130, 142, 200), rgba(200, 200, 210),
    rgba(128, 130, 142, 210),
    rgba(0, 170, 125), rgba(230, 110, 20), kSkyBlue, rgba(195, 195, 200),
    rgba(86, 180, 233, 110), kSkyBlue, rgba(230, 110, 20),
    rgba(0, 170, 125), rgba(230, 110, 20), rgba(240, 170, 0), rgba(0, 0, 0, 220),
    kSkyBlue, kPurple,
    rgba(235, 235, 240), rgba(150, 150, 156), rgba(22, 24, 28, 225),
    rgba(70, 200, 150), rgba(255, 140, 90), rgba(120, 185, 255),
    rgba(230, 180, 80), rgba(120, 190, 240), rgba(255, 150, 100),
    rgba(165, 165, 170), rgba(110, 84, 20),
    rgba(30, 44, 62), rgba(46, 43, 34),
    {rgba(86, 180, 233), rgba(34, 119, 102), rgba(204, 121, 167), rgba(136, 68, 221), rgba(102, 119, 17),
     rgba(187, 255, 136), rgba(235, 235, 235), rgba(153, 170, 119)},
};

// High contrast, light: black text on white, solid obstacles, stronger grid and outlines.
constexpr Palette kLightHigh = {
    rgba(255, 255, 255), rgba(215, 215, 215), rgba(120, 120, 120),
    rgba(0, 0, 0), rgba(60, 60, 68, 235), rgba(0, 0, 0),
    rgba(60, 60, 68, 235),
    rgba(0, 140, 100), rgba(200, 80, 0), rgba(0, 100, 170), rgba(0, 0, 0),
    rgba(0, 100, 170, 120), rgba(0, 100, 170), rgba(200, 80, 0),
    rgba(0, 140, 100), rgba(200, 80, 0), kOrange, rgba(0, 0, 0, 255),
    rgba(0, 100, 170), rgba(190, 100, 150),
    rgba(0, 0, 0), rgba(60, 60, 60), rgba(255, 255, 255, 245),
    rgba(0, 95, 64), rgba(150, 50, 0), rgba(0, 60, 120),
    rgba(110, 70, 0), rgba(0, 70, 130), rgba(130, 40, 0),
    rgba(60, 60, 60), rgba(250, 210, 110),
    rgba(255, 255, 255), rgba(255, 255, 255),
    {rgba(0, 114, 178), rgba(0, 158, 115), rgba(204, 121, 167), rgba(51, 34, 136), rgba(213, 94, 0),
     rgba(120, 60, 0), rgba(0, 0, 0), rgba(170, 51, 119)},
};

// High contrast, dark: white text on black.
constexpr Palette kDarkHigh = {
    rgba(0, 0, 0), rgba(50, 50, 50), rgba(130, 130, 130),
    rgba(255, 255, 255), rgba(170, 170, 180, 230), rgba(255, 255, 255),
    rgba(170, 170, 180, 230),
    rgba(0, 190, 140), rgba(255, 120, 40), rgba(110, 200, 255), rgba(255, 255, 255),
    rgba(110, 200, 255, 120), rgba(110, 200, 255), rgba(255, 120, 40),
    rgba(0, 190, 140), rgba(255, 120, 40), rgba(255, 190, 0), rgba(0, 0, 0, 255),
    rgba(110, 200, 255), rgba(230, 140, 190),
    rgba(255, 255, 255), rgba(200, 200, 200), rgba(0, 0, 0, 240),
    rgba(90, 230, 170), rgba(255, 160, 110), rgba(150, 200, 255),
    rgba(250, 200, 90), rgba(150, 210, 255), rgba(255, 170, 120),
    rgba(210, 210, 210), rgba(120, 90, 0),
    rgba(0, 0, 0), rgba(0, 0, 0),
    {rgba(110, 200, 255), rgba(85, 153, 34), rgba(230, 140, 190), rgba(153, 51, 187), rgba(85, 102, 68),
     rgba(187, 187, 136), rgba(255, 255, 255), rgba(204, 68, 119)},
};

Look g_look;
Look g_requested;

}  // namespace

namespace detail {
Palette g_active = kLight;
}  // namespace detail

const Palette& palette_of(Look look) {
  if (look.dark) return look.high_contrast ? kDarkHigh : kDark;
  return look.high_contrast ? kLightHigh : kLight;
}

Look look() { return g_look; }

void request_look(Look look) { g_requested = look; }

void apply_requested_look() {
  if (!(g_requested == g_look)) set_look(g_requested);
}

void set_look(Look look) {
  g_look = g_requested = look;
  detail::g_active = palette_of(look);
  apply_style();
}

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
  ImGuiStyle& s = ImGui::GetStyle();
  if (g_look.dark) ImGui::StyleColorsDark(&s); else ImGui::StyleColorsLight(&s);
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
  // High contrast: every control has an edge (WCAG 1.4.11 asks 3:1 for a control's boundary;
  // the tinted buttons alone are about 1.3:1 on the panel).
  s.FrameBorderSize = g_look.high_contrast ? 1.0f : 0.0f;
  s.PopupBorderSize = 1.0f;
  ImVec4* c = s.Colors;
  // The accent: Okabe–Ito blue on light, its sky blue on dark.
  const ImVec4 accent = g_look.dark ? vec4(kSkyBlue) : vec4(kBlue);
  const float tint = g_look.high_contrast ? 0.10f : 0.0f;
  const auto accent_a = [&](float a) { return ImVec4(accent.x, accent.y, accent.z, a + tint); };
  if (g_look.dark) {
    c[ImGuiCol_WindowBg] = g_look.high_contrast ? ImVec4(0, 0, 0, 1) : vec4(rgba(32, 34, 38));
    c[ImGuiCol_PopupBg] = g_look.high_contrast ? ImVec4(0.05f, 0.05f, 0.05f, 1) : vec4(rgba(40, 43, 48));
    c[ImGuiCol_Text] = g_look.high_contrast ? ImVec4(1, 1, 1, 1) : vec4(rgba(230, 230, 232));
    c[ImGuiCol_FrameBg] = vec4(rgba(52, 56, 62));
  } else {
    c[ImGuiCol_WindowBg] = g_look.high_contrast ? ImVec4(1, 1, 1, 1) : ImVec4(0.96f, 0.96f, 0.95f, 1.0f);
    c[ImGuiCol_Text] = g_look.high_contrast ? ImVec4(0, 0, 0, 1) : ImVec4(0.10f, 0.10f, 0.12f, 1.0f);
  }
  c[ImGuiCol_ChildBg] = ImVec4(0, 0, 0, 0);
  c[ImGuiCol_Button] = accent_a(0.16f);
  c[ImGuiCol_ButtonHovered] = accent_a(0.32f);
  c[ImGuiCol_ButtonActive] = accent_a(0.48f);
  c[ImGuiCol_Header] = accent_a(0.16f);
  c[ImGuiCol_HeaderHovered] = accent_a(0.28f);
  c[ImGuiCol_HeaderActive] = accent_a(0.40f);
  if (g_look.high_contrast) c[ImGuiCol_Border] = c[ImGuiCol_Text];
  // ImGui's light grey (0.6) is 2.6:1 on the panel; secondary text must read too (4.5:1).
  c[ImGuiCol_TextDisabled] = vec4(kTextDim);
}

}  // namespace csl::app::theme
