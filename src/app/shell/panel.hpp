#pragma once
// The side panel's layout, shared by every lesson: sections that fold, and a cue under the panel
// when there is more to scroll to (an ImGui scrollbar alone is easy to miss). A panel's default
// state fits a 1280 x 800 window; what grows (a run's numbers, an exercise's text) folds, or
// scrolls with the cue showing.
//
// The state JSON (status().panel) says how tall the panel and its content are and which sections
// it holds, open or folded, for tests; each section's header is a control in page_state's
// buttons ("section:<title>"), so a test presses it with the mouse.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace csl::app::panel {

/// A section heading that folds: true while open (draw its content then). `open` is its state
/// the first time it is drawn in a lesson; after that the student's choice holds.
bool fold(const char* title, bool open = true);

/// The panel, once a frame: begin() opens its scrolling child window `width` wide, filling the
/// height left; end() closes it and, when its content is taller than that height, draws a row
/// under it with a cue ("more below", or "back to the top" at the end) that scrolls on a click.
/// The row takes its own space (over the content, a click on it would reach what lies under).
/// By touch, a vertical swipe that starts in the panel scrolls it (panel.cpp: follow_finger).
void begin(float width);
void end();

/// {height, content, scroll, scroll_max, more_below, cue, sections: [{title, open}]} (logical px).
nlohmann::json state();

}  // namespace csl::app::panel
