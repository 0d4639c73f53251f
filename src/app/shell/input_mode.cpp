#include "app/shell/input_mode.hpp"

#include <algorithm>

namespace csl::app::input {
namespace {
bool g_touch = false;
Pinch g_pinch;
}  // namespace

bool touch() { return g_touch; }
void set_touch(bool on) { g_touch = on; }
const Pinch& pinch() { return g_pinch; }
void set_pinch(const Pinch& p) { g_pinch = p; }
float reach(float mouse_px) { return g_touch ? std::max(mouse_px, 22.0f) : mouse_px; }

}  // namespace csl::app::input
