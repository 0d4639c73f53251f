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

// The look: light or dark, normal or high contrast. Each role below is the active look's
// colour, read at draw time (set_look changes them all, and ImGui's style, between frames).
struct Palette {
  ImU32 canvas_bg, grid_minor, grid_major, frame, obstacle_fill, obstacle_edge, cobstacle;
  ImU32 start, goal, preview, label, selected_fill, selected_edge, warning, free, hit;
  ImU32 path, path_outline, robot, current;
  ImU32 ink;        ///< the strongest stroke on the canvas (black on light, near white on dark)
  ImU32 faint;      ///< guides and construction lines on the canvas
  ImU32 label_box;  ///< the translucent box behind a label on the canvas
  // Text in colour on the panel: each at least 4.5:1 there (WCAG 2.1 AA, 1.4.3), as
  // tests/e2e/colour.test.mjs checks through the `theme` command, in every look.
  ImU32 text_good;    ///< a path found, a check passed
  ImU32 text_bad;     ///< no path, a collision missed, stuck
  ImU32 text_key;     ///< a headline figure
  ImU32 text_amount;  ///< a distance being measured
  ImU32 text_log;     ///< the event log's newest line
  ImU32 text_notice;  ///< the one-line notice
  ImU32 text_dim;     ///< secondary text (ImGui's TextDisabled)
  ImU32 restore_button;  ///< "Restore my previous work" stands out
  ImU32 card_welcome;    ///< the first visit's welcome box on the panel
  ImU32 card_problem;    ///< the homework card on the panel (its text is the panel's)
  /// Roadmap components' colours, cycled. The largest component is usually 0 (it holds the
  /// start): the calm blue; then hues that stay at least CIEDE2000 10 apart from each other and
  /// from the path for every dichromacy (Machado 2009), and 3:1 on the canvas.
  ImU32 components[8];
};

struct Look {
  bool dark = false;
  bool high_contrast = false;
  bool operator==(const Look& o) const { return dark == o.dark && high_contrast == o.high_contrast; }
};

namespace detail {
extern Palette g_active;  // constant-initialised (light) in theme.cpp, before any other static
}  // namespace detail
/// The palette of a look.
const Palette& palette_of(Look look);

/// The look in use; a new one now (palette and ImGui style: between frames), or from the next
/// frame on (`apply_requested_look` at a frame's start: a menu or an API call asks mid-frame).
Look look();
void set_look(Look look);
void request_look(Look look);
void apply_requested_look();

// Roles, named as constants because they are read like constants: they change only with the look.
inline const ImU32& kCanvasBg = detail::g_active.canvas_bg;
inline const ImU32& kGridMinor = detail::g_active.grid_minor;
inline const ImU32& kGridMajor = detail::g_active.grid_major;
inline const ImU32& kFrame = detail::g_active.frame;
inline const ImU32& kObstacleFill = detail::g_active.obstacle_fill;
inline const ImU32& kObstacleEdge = detail::g_active.obstacle_edge;
inline const ImU32& kCObstacle = detail::g_active.cobstacle;
inline const ImU32& kStart = detail::g_active.start;
inline const ImU32& kGoal = detail::g_active.goal;
inline const ImU32& kPreview = detail::g_active.preview;
inline const ImU32& kLabel = detail::g_active.label;
inline const ImU32& kSelectedFill = detail::g_active.selected_fill;
inline const ImU32& kSelectedEdge = detail::g_active.selected_edge;
inline const ImU32& kWarning = detail::g_active.warning;
inline const ImU32& kFree = detail::g_active.free;
inline const ImU32& kHit = detail::g_active.hit;
inline const ImU32& kPath = detail::g_active.path;                  // orange, wide
inline const ImU32& kPathOutline = detail::g_active.path_outline;
inline const ImU32& kRobot = detail::g_active.robot;
inline const ImU32& kCurrent = detail::g_active.current;            // the step being shown
inline const ImU32& kInk = detail::g_active.ink;
inline const ImU32& kFaint = detail::g_active.faint;
inline const ImU32& kLabelBox = detail::g_active.label_box;
inline const ImU32& kTextGood = detail::g_active.text_good;
inline const ImU32& kTextBad = detail::g_active.text_bad;
inline const ImU32& kTextKey = detail::g_active.text_key;
inline const ImU32& kTextAmount = detail::g_active.text_amount;
inline const ImU32& kTextLog = detail::g_active.text_log;
inline const ImU32& kTextNotice = detail::g_active.text_notice;
inline const ImU32& kTextDim = detail::g_active.text_dim;
inline const ImU32& kRestoreButton = detail::g_active.restore_button;
inline const ImU32& kCardWelcome = detail::g_active.card_welcome;
inline const ImU32& kCardProblem = detail::g_active.card_problem;
inline const ImU32 (&kComponents)[8] = detail::g_active.components;
inline constexpr unsigned kComponentCount = 8;

/// The colour as ImGui's float RGBA (TextColored, PushStyleColor).
inline ImVec4 vec4(ImU32 c) { return ImGui::ColorConvertU32ToFloat4(c); }
/// Black or white, whichever reads better on `fill` (WCAG contrast): a marker's letter.
ImU32 text_on(ImU32 fill);
ImU32 component_color(int component, unsigned alpha = 255);

/// Applies the lab's ImGui style (rounded, readable spacing) in the look in use.
void apply_style();

}  // namespace csl::app::theme
