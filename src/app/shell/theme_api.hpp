#pragma once
// The `theme` API command: the colours that carry meaning in the lab, by role, as the app
// draws them. The accessibility tests read the real values from here (colour-vision
// simulation, contrast) instead of a copy that could drift from theme.hpp.
#include "app/shell/js_api.hpp"

namespace csl::app::theme {

/// Registers `theme`: {colours: {role: [r, g, b, a]}, components: [[r, g, b, a], ...],
/// text: [{name, fg, bg}]: text as drawn over its background (alpha already composited).
void register_api(JsApi& api);

}  // namespace csl::app::theme
