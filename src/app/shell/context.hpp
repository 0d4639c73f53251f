#pragma once
// What lessons share: the playback controls, the event log, notices for the user, the views
// the JS API can address, and frame timing.
#include <map>
#include <string>

#include "app/shell/event_log.hpp"
#include "app/views/plot.hpp"
#include "app/views/workspace_view.hpp"

namespace csl::app {

/// Play/pause and speed of the running algorithm, shared by all lessons.
struct Playback {
  bool playing = false;
  float steps_per_second = 20.0f;
  double carry = 0.0;  ///< fractional steps owed from earlier frames
  /// Steps to take this frame while playing (dt in seconds).
  int due(double dt);
};

struct LabContext {
  Playback playback;
  EventLog log;
  std::string notice;          ///< one line shown prominently (a refused edit, a warning)
  double notice_until = 0.0;   ///< ImGui time after which it fades
  /// How many notices were shown: the same words again are a new notice (the page's copy reads it).
  int notices = 0;
  /// The lesson's views by name ("workspace", "cspace"), for the JS API's coordinate queries and
  /// the F key (fit the view).
  std::map<std::string, WorkspaceView*> views;
  /// The lesson's plots by name ("bound"): the JS API maps data points through them as through views.
  std::map<std::string, const Plot*> plots;
  /// Other views drawn this frame (a 3-D surface, a picture), by name, as screen rectangles:
  /// with `views` and `plots` they make status().layout.views.
  std::map<std::string, std::pair<ImVec2, ImVec2>> areas;
  /// The app's layout (app_layout.cpp): narrow or short screens get the compact one.
  bool compact = false;
  /// The top bar's buttons are 44 px high (ui::bar_button): by touch, in the compact layout and
  /// in the wide one where the screen is tall enough to spare the rows (app_layout.cpp).
  bool tall_bar = false;

  /// Shows a one-line notice for a few seconds.
  void notify(const std::string& text, double seconds = 5.0);
};

}  // namespace csl::app
