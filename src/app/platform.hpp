#pragma once
// The window, the GL context and the ImGui backends, with one main-loop body for the desktop
// and the browser (where Emscripten drives the loop). Everything SDL/GL/Emscripten-specific
// stays in platform.cpp.
#include <functional>

struct SDL_Window;

namespace csl::app {

struct PlatformOptions {
  const char* title = "C-Space Lab";
  int width = 1280;   ///< desktop window size; in the browser the canvas's CSS size wins
  int height = 800;
  long max_frames = -1;  ///< desktop only: quit after this many frames (smoke tests); -1 = never
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

 private:
  static void frame_trampoline(void* self);
  void frame_once();
  void sync_canvas_size();
  void update_pixel_ratio();

  SDL_Window* window_ = nullptr;
  void* gl_context_ = nullptr;
  std::function<void()> frame_;
  float pixel_ratio_ = 0.0f;  // 0 = fonts not built yet
  long frames_ = 0;
  long max_frames_ = -1;
  bool quit_ = false;
};

}  // namespace csl::app
