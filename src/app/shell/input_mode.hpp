#pragma once
// How the student points, for the views and the layout: a finger or a mouse, and a two-finger
// gesture in progress. The platform sets it from SDL's events each frame (platform.cpp).
//
// Why here and not in ImGui: ImGui 1.86 knows one mouse. SDL turns the first finger into that
// mouse and drops the others, so a pinch would be a drag of whatever lies under the first finger.
// The platform sees every finger, reports the pinch here and holds ImGui's mouse still meanwhile.
#include "imgui.h"

namespace csl::app::input {

/// A two-finger gesture this frame: the fingers' midpoint (logical px), how much their distance
/// grew since the last frame (a factor), and how far the midpoint moved.
struct Pinch {
  bool active = false;
  ImVec2 center{0, 0};
  float scale = 1.0f;
  ImVec2 pan{0, 0};
};

/// The last pointer was a finger (or the device's only pointer is coarse).
bool touch();
void set_touch(bool on);

const Pinch& pinch();
void set_pinch(const Pinch& p);

/// How far (logical px) the finger that pressed first has been from where it pressed, at most,
/// since it pressed; infinity once a second finger joined (a pinch is no long press). Read from
/// SDL's finger events themselves: ImGui's mouse, which SDL makes of that finger, can lag them
/// by frames on a busy page, and a long press must not be mistaken for a slow drag.
float finger_travel();
void set_finger_travel(float px);

/// A handle's reach in logical px: `mouse_px` for a mouse, at least 22 (a 44 px target, WCAG's
/// target size) for a finger, which covers what it touches.
float reach(float mouse_px);

}  // namespace csl::app::input
