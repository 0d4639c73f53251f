#include "app/shell/input_mode.hpp"

#include <algorithm>

namespace csl::app::input {
namespace {
bool g_touch = false;
Pinch g_pinch;
float g_travel = 0.0f;
}  // namespace

bool touch() { return g_touch; }
void set_touch(bool on) { g_touch = on; }
const Pinch& pinch() { return g_pinch; }
void set_pinch(const Pinch& p) { g_pinch = p; }
float finger_travel() { return g_travel; }
void set_finger_travel(float px) { g_travel = px; }
float reach(float mouse_px) { return g_touch ? std::max(mouse_px, 22.0f) : mouse_px; }

}  // namespace csl::app::input
