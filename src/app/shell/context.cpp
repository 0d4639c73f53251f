#include "app/shell/context.hpp"

#include <cmath>

#include "imgui.h"

namespace csl::app {

int Playback::due(double dt) {
  if (!playing) {
    carry = 0.0;
    return 0;
  }
  // Frames can stall (a hidden tab): never try to catch up more than a quarter second.
  carry += std::fmin(dt, 0.25) * static_cast<double>(steps_per_second);
  const double whole = std::floor(carry);
  carry -= whole;
  return static_cast<int>(whole);
}

void LabContext::notify(const std::string& text, double seconds) {
  notice = text;
  notice_until = ImGui::GetTime() + seconds;
  ++notices;
}

}  // namespace csl::app
