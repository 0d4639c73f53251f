#pragma once
// The UI fonts, rasterised for the screen's pixel ratio.
#include "imgui.h"

namespace csl::app {

/// Fonts of the app, valid after build_fonts().
struct Fonts {
  ImFont* body = nullptr;   ///< text and widgets
  ImFont* small = nullptr;  ///< axis labels and annotations
  ImFont* title = nullptr;  ///< headings
};
const Fonts& fonts();

/// (Re)builds the font atlas with glyphs rasterised at `pixel_ratio` device pixels per
/// logical pixel, and scales them back with FontGlobalScale. Call between frames.
void build_fonts(float pixel_ratio);

}  // namespace csl::app
