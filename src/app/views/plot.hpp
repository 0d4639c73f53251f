#pragma once
// A small 2-D plot for the lessons: linear or log10 axes with labelled ticks, line series,
// points with error bars, a legend. Drawn with ImGui's draw list.
#include <string>
#include <vector>

#include "imgui.h"

namespace csl::app {

class Plot {
 public:
  struct Axis {
    double lo, hi;
    bool log = false;
    std::string label;
  };
  /// Lays out the plot at the cursor and draws its frame, grid and tick labels.
  void begin(const char* id, ImVec2 size, const Axis& x, const Axis& y);
  /// A polyline through (xs[i], ys[i]); points outside the y range are clipped.
  void line(const std::vector<double>& xs, const std::vector<double>& ys, ImU32 color, float thickness,
            const char* legend);
  /// Points with vertical error bars [lo, hi].
  void points(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& lo,
              const std::vector<double>& hi, ImU32 color, const char* legend);
  /// Shades the band y >= from (e.g. "vacuous": probabilities above 1).
  void shade_above(double from, ImU32 color, const char* label);
  /// Draws the legend; call last.
  void end();
  ImVec2 to_screen(double x, double y) const;
  /// The whole plot on screen, labels included (for the layout report).
  ImVec2 box_min() const { return box_min_; }
  ImVec2 box_max() const { return box_max_; }

 private:
  double map(const Axis& a, double v) const;
  ImVec2 min_{0, 0}, max_{0, 0};  // the plotting area
  ImVec2 box_min_{0, 0}, box_max_{0, 0};  // the whole widget
  Axis x_{0, 1, false, ""}, y_{0, 1, false, ""};
  std::vector<std::pair<std::string, ImU32>> legend_;
  std::string shade_label_;
};

}  // namespace csl::app
