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
/// Colours for roadmap components, cycled (Okabe–Ito minus the roles above, then tints).
ImU32 component_color(int component, unsigned alpha = 255);

/// Applies the lab's ImGui style (light, rounded, readable spacing).
void apply_style();

}  // namespace csl::app::theme
