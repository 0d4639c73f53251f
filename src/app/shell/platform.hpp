#pragma once
// The window, the GL context and the ImGui backends, with one main-loop body for the desktop
// and the browser (where Emscripten drives the loop). Everything SDL/GL/Emscripten-specific
// stays in platform.cpp.
#include <array>
#include <functional>
#include <map>
#include <vector>

#include <SDL_events.h>

#include "imgui.h"

struct SDL_Window;

namespace csl::app {

struct PlatformOptions {
  const char* title = "C-Space Lab";
  int width = 1280;   ///< desktop window size; in the browser the canvas's CSS size wins
  int height = 800;
  long max_frames = -1;  ///< desktop only: quit after this many frames (smoke tests); -1 = never
};

/// Frame timing over the last 120 frames: the interval between frames (what the user sees) and
/// the CPU time spent building and submitting one.
struct FrameStats {
  double mean_interval_ms = 0, p95_interval_ms = 0, max_interval_ms = 0;
  double mean_cpu_ms = 0, p95_cpu_ms = 0, max_cpu_ms = 0;
  double mean_ui_ms = 0, p95_ui_ms = 0, max_ui_ms = 0;  ///< of which building the UI (no GL)
  double vertices = 0;                                   ///< in the last frame's draw data
};

class Platform {
 public:
  /// Opens the window and GL context and sets up ImGui. Prints the reason and returns false on failure.
  bool init(const PlatformOptions& options);
  /// Calls frame() between ImGui's NewFrame and Render until the window closes (desktop) or
  /// for ever (browser). Returns on the desktop only.
  void run(std::function<void()> frame);
  void shutdown();

  /// Device pixels per CSS/logical pixel (2 on a typical HiDPI screen).
  float pixel_ratio() const { return pixel_ratio_; }
  long frame_count() const { return frames_; }
  const FrameStats& frame_stats() const { return stats_; }

 private:
  static void frame_trampoline(void* self);
  void frame_once();
  void sync_canvas_size();
  void update_pixel_ratio();
  // Fingers and mice (input_mode.hpp): which one points, and a two-finger gesture.
  void track_pointer(const SDL_Event& event);
  void update_gesture();
  void hold_mouse_during_gesture();

  // A key release delivered a frame later (and the events after it with it, left in SDL's
  // queue): one that arrived in the frame of its press, or a modifier's after any press (ImGui
  // 1.86 reads keys as per-frame state: a press and release in one frame would go unseen, and
  // Ctrl+Z released at once would be a plain Z). At most one.
  std::vector<SDL_Event> deferred_;
  SDL_Window* window_ = nullptr;
  void* gl_context_ = nullptr;
  std::function<void()> frame_;
  float pixel_ratio_ = 0.0f;  // 0 = fonts not built yet
  long frames_ = 0;
  static constexpr std::size_t kTimed = 120;
  std::array<double, kTimed> interval_ms_{}, cpu_ms_{}, ui_ms_{};
  double last_start_ = -1.0;
  FrameStats stats_;
  long max_frames_ = -1;
  bool quit_ = false;
  bool text_mode_ = false;  // the canvas takes text from the page (a text field has the keyboard)
  // The fingers down (logical px), where the first came down, and a gesture since then: while a
  // second finger is or was down, ImGui's mouse stays where the first finger pressed and is let
  // go (what it began dragging goes back there), until every finger is up.
  std::map<long long, ImVec2> fingers_;
  ImVec2 first_press_{0, 0};
  long long first_finger_ = -1;  // the finger that pressed first (its travel: input::finger_travel)
  bool gesture_ = false;   // since a second finger came down, until every finger is up
  int gesture_frames_ = 0;
  bool pinching_ = false;  // two fingers down now (and last frame's center and spread are set)
  ImVec2 last_center_{0, 0};
  float last_spread_ = 0.0f;
};

}  // namespace csl::app
