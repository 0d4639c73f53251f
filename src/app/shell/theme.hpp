#pragma once
// Colours and the ImGui style of the lab. The data colours are the Okabe–Ito palette, which
// stays distinguishable for the common kinds of colour blindness; shapes and labels carry the
// meaning too, never colour alone.
#include "imgui.h"

namespace csl::app::theme {

constexpr ImU32 rgba(unsigned r, unsigned g, unsigned b, unsigned a = 255) {
  return (static_cast<ImU32>(a) << 24) | (static_cast<ImU32>(b) << 16) |
         (static_cast<ImU32>(g) << 8) | static_cast<ImU32>(r);
}
/// The colour with its alpha replaced (0..255).
constexpr ImU32 with_alpha(ImU32 c, unsigned a) { return (c & 0x00FFFFFFu) | (static_cast<ImU32>(a) << 24); }

// Okabe–Ito.
inline constexpr ImU32 kOrange = rgba(230, 159, 0);
inline constexpr ImU32 kSkyBlue = rgba(86, 180, 233);
inline constexpr ImU32 kGreen = rgba(0, 158, 115);
inline constexpr ImU32 kYellow = rgba(240, 228, 66);
inline constexpr ImU32 kBlue = rgba(0, 114, 178);
inline constexpr ImU32 kVermillion = rgba(213, 94, 0);
inline constexpr ImU32 kPurple = rgba(204, 121, 167);
inline constexpr ImU32 kBlack = rgba(0, 0, 0);

// Roles.
inline constexpr ImU32 kCanvasBg = rgba(255, 255, 255);
inline constexpr ImU32 kGridMinor = rgba(232, 232, 232);
inline constexpr ImU32 kGridMajor = rgba(200, 200, 200);
inline constexpr ImU32 kFrame = rgba(90, 90, 90);
inline constexpr ImU32 kObstacleFill = rgba(96, 96, 104, 200);
inline constexpr ImU32 kObstacleEdge = rgba(40, 40, 48);
inline constexpr ImU32 kStart = kGreen;
inline constexpr ImU32 kGoal = kVermillion;
inline constexpr ImU32 kPreview = kBlue;
inline constexpr ImU32 kLabel = rgba(70, 70, 70);
inline constexpr ImU32 kSelectedFill = rgba(0, 114, 178, 110);
inline constexpr ImU32 kSelectedEdge = rgba(0, 114, 178);
inline constexpr ImU32 kWarning = rgba(213, 94, 0);
inline constexpr ImU32 kFree = kGreen;
inline constexpr ImU32 kHit = kVermillion;
inline constexpr ImU32 kPath = rgba(230, 159, 0);          // orange, wide
inline constexpr ImU32 kPathOutline = rgba(60, 40, 0, 200);
inline constexpr ImU32 kRobot = rgba(0, 114, 178);
inline constexpr ImU32 kCurrent = rgba(204, 121, 167);     // the step being shown

// Text in colour on the panel (WindowBg, about (245, 245, 242)): each at least 4.5:1 there
// (WCAG 2.1 AA, 1.4.3), as tests/e2e/colour.test.mjs checks through the `theme` command.
inline constexpr ImU32 kTextGood = rgba(0, 115, 77);       // a path found, a check passed
inline constexpr ImU32 kTextBad = rgba(179, 64, 0);        // no path, a collision missed, stuck
inline constexpr ImU32 kTextKey = rgba(0, 77, 140);        // a headline figure
inline constexpr ImU32 kTextAmount = rgba(140, 92, 0);     // a distance being measured
inline constexpr ImU32 kTextLog = rgba(0, 89, 153);        // the event log's newest line
inline constexpr ImU32 kTextNotice = rgba(153, 51, 0);     // the one-line notice
inline constexpr ImU32 kTextDim = rgba(97, 97, 97);        // secondary text (ImGui's TextDisabled)
inline constexpr ImU32 kRestoreButton = rgba(250, 219, 140);  // "Restore my previous work" stands out

/// The colour as ImGui's float RGBA (TextColored, PushStyleColor).
inline ImVec4 vec4(ImU32 c) { return ImGui::ColorConvertU32ToFloat4(c); }
/// Black or white, whichever reads better on `fill` (WCAG contrast): a marker's letter.
ImU32 text_on(ImU32 fill);
/// Roadmap components' colours, cycled. The largest component is usually 0 (it holds the
/// start): the calm blue; then hues that stay at least CIEDE2000 10 apart from each other and
/// from the path for every dichromacy (Machado 2009), and 3:1 on the canvas. (Okabe–Ito's sky
/// blue, a violet and an olive in this place came within 6 to 8 of a neighbour.)
inline constexpr ImU32 kComponents[] = {rgba(0, 114, 178), rgba(0, 158, 115), rgba(204, 121, 167), rgba(51, 34, 136),
                                        rgba(213, 94, 0),  rgba(120, 60, 0),   rgba(0, 0, 0),       rgba(170, 51, 119)};
inline constexpr unsigned kComponentCount = sizeof kComponents / sizeof kComponents[0];
ImU32 component_color(int component, unsigned alpha = 255);

/// Applies the lab's ImGui style (light, rounded, readable spacing).
void apply_style();

}  // namespace csl::app::theme
