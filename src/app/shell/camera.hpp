#pragma once
// Where a lesson's views look, so that a snapshot (a Share link, an embed, autosave) shows the
// same region: each plane view's centre and zoom, each 3-D view's turn (and zoom).
//
//   {"workspace": [0.31, 0.62, 4], "torus": [1.2, 0.4], "volume": [0.8, 0.5, 1.44]}
//
// a plane's centre x, y (the world point at the middle of its canvas) and zoom (1: Fit, the whole
// rectangle), a 3-D view's yaw and pitch in radians, and for a 3-D view that zooms (the volume
// view) its zoom in [0.5, 4] when it is not 1 (left out, it is 1: links written before the
// volume's zoom travelled still read the same). Names are the lesson's views
// (Lesson::views_kept, the names of status().layout.views). A link writes the same numbers as
// camera=workspace:0.31,0.62,4~torus:1.2,0.4 (web/lab-url.js), rounded to what a pixel needs, so
// links stay short.
#include <nlohmann/json.hpp>

#include <string>

#include "app/shell/lesson.hpp"

namespace csl::app {

/// The lesson's cameras. `all`: every view's; otherwise only those the user moved (a plane that
/// is Fit and a 3-D view at its first turn are left out: links of an unzoomed lab stay as they
/// were). Centres to about 1/10000 of the rectangle over the zoom, zooms to 6 digits, angles to
/// 1e-4 rad: each within a hundredth of a pixel of the camera on screen.
nlohmann::json cameras_json(Lesson& lesson, bool all);

/// Sets the lesson's cameras from such JSON (views not named keep theirs). Everything is
/// checked before anything changes: an unknown view, a list of the wrong length (a zoom for a 3-D
/// view that does not zoom), a plane's zoom outside [0.5, 200] or centre more than the
/// rectangle's width (height) beside it, a pitch outside +-1.5, a yaw outside [-pi, pi] or a 3-D
/// zoom outside [0.5, 4] throw ApiError naming the view and the value.
void set_cameras(Lesson& lesson, const nlohmann::json& cameras);

/// The cameras of cameras_json(lesson, false) in words, for the event log: "the cspace zoomed
/// 1.73x, the torus turned"; "" when all are as they start.
std::string cameras_text(const nlohmann::json& cameras);

}  // namespace csl::app
