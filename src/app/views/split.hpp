#pragma once
// Two views of a lesson side by side, or one over the other where the area is taller than wide
// (a phone held upright, a tablet in portrait): each view then gets the whole width instead of
// half of a narrow one.
#include "imgui.h"

namespace csl::app {

struct Split {
  bool stacked = false;
  ImVec2 first{0, 0}, second{0, 0};
};

/// Splits `size` one way or the other, `share` of it to the first view (of the width side by
/// side, of the height stacked), the item spacing between them.
inline Split split_as(ImVec2 size, bool stacked, float share = 0.5f) {
  const ImVec2 gap = ImGui::GetStyle().ItemSpacing;
  Split s;
  s.stacked = stacked;
  if (stacked) {
    const float h = share * (size.y - gap.y);
    s.first = ImVec2(size.x, h);
    s.second = ImVec2(size.x, size.y - gap.y - h);
  } else {
    const float w = share * (size.x - gap.x);
    s.first = ImVec2(w, size.y);
    s.second = ImVec2(size.x - gap.x - w, size.y);
  }
  return s;
}

/// Stacked where `size` is taller than wide.
inline Split split(ImVec2 size, float share = 0.5f) { return split_as(size, size.x < size.y, share); }

/// Between the two views: on the same row unless stacked.
inline void between(const Split& s) {
  if (!s.stacked) ImGui::SameLine();
}

}  // namespace csl::app
