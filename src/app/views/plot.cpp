#include "app/views/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/shell/fonts.hpp"
#include "app/shell/theme.hpp"

namespace csl::app {

double Plot::map(const Axis& a, double v) const {
  if (a.log) return (std::log10(std::max(v, 1e-300)) - std::log10(a.lo)) / (std::log10(a.hi) - std::log10(a.lo));
  return (v - a.lo) / (a.hi - a.lo);
}

ImVec2 Plot::to_screen(double x, double y) const {
  return ImVec2(min_.x + static_cast<float>(map(x_, x)) * (max_.x - min_.x),
                max_.y - static_cast<float>(map(y_, y)) * (max_.y - min_.y));
}

void Plot::begin(const char* id, ImVec2 size, const Axis& x, const Axis& y) {
  x_ = x;
  y_ = y;
  legend_.clear();
  shade_label_.clear();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  box_min_ = o;
  box_max_ = ImVec2(o.x + size.x, o.y + size.y);
  ImFont* font = fonts().small;
  const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
  // The y axis's label on a line of its own above the plot, clear of the top tick's number.
  min_ = ImVec2(o.x + 64.0f, o.y + fs + 12.0f);
  max_ = ImVec2(o.x + size.x - 30.0f, o.y + size.y - 44.0f);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(min_, max_, theme::kCanvasBg);
  // Ticks: decades on log axes, five steps on linear ones.
  const auto ticks = [](const Axis& a) {
    std::vector<double> t;
    if (a.log) {
      for (double e = std::ceil(std::log10(a.lo)); e <= std::floor(std::log10(a.hi)) + 1e-9; e += 1.0) t.push_back(std::pow(10.0, e));
    } else {
      for (int i = 0; i <= 5; ++i) t.push_back(a.lo + (a.hi - a.lo) * i / 5.0);
    }
    return t;
  };
  char text[32];
  for (double v : ticks(x_)) {
    const float sx = to_screen(v, y_.lo).x;
    dl->AddLine(ImVec2(sx, min_.y), ImVec2(sx, max_.y), theme::kGridMinor);
    std::snprintf(text, sizeof text, x_.log ? "%g" : "%.3g", v);
    const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, text);
    dl->AddText(font, fs, ImVec2(sx - 0.5f * ts.x, max_.y + 4), theme::kLabel, text);
  }
  for (double v : ticks(y_)) {
    const float sy = to_screen(x_.lo, v).y;
    dl->AddLine(ImVec2(min_.x, sy), ImVec2(max_.x, sy), theme::kGridMinor);
    std::snprintf(text, sizeof text, y_.log ? "%g" : "%.3g", v);
    const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, text);
    dl->AddText(font, fs, ImVec2(min_.x - ts.x - 6, sy - 0.5f * ts.y), theme::kLabel, text);
  }
  dl->AddRect(min_, max_, theme::kFrame);
  const ImVec2 xs = font->CalcTextSizeA(fs, 1e9f, 0.0f, x_.label.c_str());
  dl->AddText(font, fs, ImVec2(0.5f * (min_.x + max_.x - xs.x), max_.y + 22), theme::kLabel, x_.label.c_str());
  dl->AddText(font, fs, ImVec2(o.x + 2, o.y + 2), theme::kLabel, y_.label.c_str());
}

void Plot::line(const std::vector<double>& xs, const std::vector<double>& ys, ImU32 color, float thickness,
                const char* legend) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(min_, max_, true);
  std::vector<ImVec2> pts;
  for (std::size_t i = 0; i < xs.size(); ++i)
    if (std::isfinite(ys[i]) && (!y_.log || ys[i] > 0)) pts.push_back(to_screen(xs[i], ys[i]));
  if (pts.size() >= 2) dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), color, 0, thickness);
  dl->PopClipRect();
  if (legend) legend_.emplace_back(legend, color);
}

void Plot::points(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& lo,
                  const std::vector<double>& hi, ImU32 color, const char* legend) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(min_, max_, true);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    // A rate of 0 has no place on a log axis: draw it at the bottom edge, hollow.
    const double floor = y_.log ? y_.lo : -1e300;
    const ImVec2 a = to_screen(xs[i], std::max(lo[i], floor)), b = to_screen(xs[i], std::max(hi[i], floor));
    dl->AddLine(a, b, color, 1.5f);
    dl->AddLine(ImVec2(a.x - 4, a.y), ImVec2(a.x + 4, a.y), color, 1.5f);
    dl->AddLine(ImVec2(b.x - 4, b.y), ImVec2(b.x + 4, b.y), color, 1.5f);
    const bool zero = y_.log && ys[i] <= y_.lo;
    const ImVec2 c = to_screen(xs[i], std::max(ys[i], floor));
    if (zero) dl->AddCircle(c, 4.5f, color, 12, 2.0f);
    else dl->AddCircleFilled(c, 4.5f, color, 12);
  }
  dl->PopClipRect();
  if (legend) legend_.emplace_back(legend, color);
}

void Plot::shade_above(double from, ImU32 color, const char* label) {
  const float sy = std::max(min_.y, std::min(max_.y, to_screen(x_.lo, from).y));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(min_, ImVec2(max_.x, sy), color);
  if (label) shade_label_ = label;  // drawn by end(), over the lines
}

void Plot::end() {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  if (!shade_label_.empty()) {  // on a backing of the canvas's colour, so lines do not cross it
    const ImVec2 size = ImGui::CalcTextSize(shade_label_.c_str());
    const ImVec2 at(max_.x - 8 - size.x, min_.y + 4);
    dl->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + size.x + 3, at.y + size.y + 1),
                      theme::with_alpha(theme::kCanvasBg, 220), 3.0f);
    dl->AddText(at, theme::kLabel, shade_label_.c_str());
  }
  float y = max_.y - 8.0f - 18.0f * static_cast<float>(legend_.size());
  for (const auto& [text, color] : legend_) {
    dl->AddLine(ImVec2(min_.x + 10, y + 8), ImVec2(min_.x + 30, y + 8), color, 3.0f);
    dl->AddText(ImVec2(min_.x + 36, y), theme::kLabel, text.c_str());
    y += 18.0f;
  }
}

}  // namespace csl::app
