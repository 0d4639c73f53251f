#pragma once
// The app's side of the page around it (web/lab-shell.js): the Share, Embed and File buttons
// of the top bar, the "Reset lesson to default" confirmation, "Restore my previous work", the
// File menu's list of previous work, and the API commands the page answers through (notify,
// page_state, bundled_scenes).
//
// The buttons only ask; the page does the work (links, clipboard, downloads, file pickers,
// localStorage): a button calls the page's Module.cslPageAction(name) (EM_JS). Until a page
// shell has said hello through page_state (and always on the desktop) none of them is shown.
#include <string>
#include <vector>

#include "app/shell/context.hpp"
#include "app/shell/js_api.hpp"

namespace csl::app::web {

struct PageState {
  bool attached = false;  ///< a page shell has announced itself (page_state {attached: true})
  bool minimal = false;   ///< ui=minimal: an embed, no lesson menu
  bool welcome = false;   ///< a first visit: the panel offers the homework map (the page remembers a dismissal)
  /// The browser asks for reduced motion (prefers-reduced-motion): nothing moves by itself.
  bool reduced_motion = false;
  std::string previous;   ///< the newest previous work (shown on its button's tooltip), "" if none
  /// The page's history of previous work, newest first, one label each ("14:03 · before a link ·
  /// Step PRM"); the File menu lists them and asks for "restore-history:<i>".
  std::vector<std::string> history;
  /// The look the student chose in Display ("system", "light" or "dark"; "system", "normal" or
  /// "high"), and what the browser prefers (prefers-color-scheme: dark; prefers-contrast: more
  /// or forced-colors: active). The page keeps the choice; a link may set it for one visit.
  std::string scheme = "system";
  std::string contrast = "system";
  bool system_dark = false;
  bool system_high_contrast = false;
};

/// At most this many history entries, each label at most kMaxHistoryLabel bytes (page_state).
constexpr std::size_t kMaxHistory = 20;
constexpr std::size_t kMaxHistoryLabel = 200;
const PageState& page();
/// The student has seen the welcome: it goes, and the page remembers (page action "welcome-seen").
void dismiss_welcome();

/// Registers notify, page_state and bundled_scenes.
void register_api(JsApi& api, LabContext& ctx);

/// The width top_bar_actions needs on one line (it grows by the restore button).
float top_bar_actions_width();

/// Draws the page's actions from the cursor on (the version text alone when no page is
/// attached), and the reset confirmation when it is open. The caller places them. In the compact
/// layout by touch they are 44 px high (ui::bar_button).
void top_bar_actions(LabContext& ctx, const std::string& lesson_name);

/// Records where the last item is, under `name`, for page_state's buttons (this frame only): a
/// test, or a guided tour, presses the real control there.
void record_control(const char* name);
/// At the start of a frame: forget the last frame's controls (page_state reports this frame's).
void begin_controls();

/// Asks the page to do `name` (share, embed, import, export-scene, export-png, export-state,
/// reset, restore-previous, restore-history:<i>, open-full); a no-op without a page.
void page_action(const char* name);

}  // namespace csl::app::web
