#include "app/shell/platform.hpp"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <cstdio>
#include <cstring>

#include "app/shell/fonts.hpp"
#include "app/shell/input_mode.hpp"
#include "imgui.h"
#include "imgui_internal.h"  // the text field's place (PlatformImePos)
#include "imgui_impl_opengl3.h"
#include "imgui_impl_sdl.h"

#ifdef __EMSCRIPTEN__
#include <EGL/egl.h>
#include <GLES3/gl3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#define EMSCRIPTEN_KEEPALIVE_IF_WEB EMSCRIPTEN_KEEPALIVE
#else
#include <SDL_opengl.h>
#define EMSCRIPTEN_KEEPALIVE_IF_WEB
#endif

#ifdef __EMSCRIPTEN__
// Text that comes without a key press (a × or ² from a character palette, a compose key or an
// on-screen keyboard, a paste) goes only to an editable element, as an input event: SDL's
// Emscripten port reads key presses on the canvas alone, so such text was dropped. While a text
// field of the app has the keyboard, a hidden textarea next to the canvas takes the focus (and on
// a phone brings up its keyboard): its key events are passed on to the canvas, where SDL handles
// them as before (and cancels the textarea's own typing, so nothing arrives twice), and what
// still lands in it goes to ImGui. `on`: a field has the keyboard; x, y: where (CSS px).
EM_JS(void, csl_text_field_js, (int on, float x, float y), {
  var c = Module.canvas, t = c.cslText;
  if (!t) {
    if (!on || !c.parentNode) return;
    t = c.cslText = document.createElement("textarea");
    t.className = "lab-text-proxy";
    t.setAttribute("aria-label", "the lab's text field");
    t.setAttribute("autocomplete", "off");
    t.setAttribute("autocapitalize", "off");
    t.spellcheck = false;
    t.tabIndex = -1;
    c.parentNode.insertBefore(t, c.nextSibling);
    var pass = function(e) {
      var f = new KeyboardEvent(e.type, {key: e.key, code: e.code, location: e.location, repeat: e.repeat,
        ctrlKey: e.ctrlKey, shiftKey: e.shiftKey, altKey: e.altKey, metaKey: e.metaKey, keyCode: e.keyCode,
        charCode: e.charCode, which: e.which, bubbles: true, cancelable: true});
      if (!c.dispatchEvent(f)) e.preventDefault();
    };
    ["keydown", "keyup", "keypress"].forEach(function(type) { t.addEventListener(type, pass); });
    t.addEventListener("beforeinput", function(e) {
      // An on-screen keyboard's backspace comes as an edit of the (empty) textarea, not a key.
      if (e.inputType !== "deleteContentBackward" || t.value) return;
      e.preventDefault();
      pass({type: "keydown", key: "Backspace", code: "Backspace", keyCode: 8, which: 8, preventDefault: function() {}});
      pass({type: "keyup", key: "Backspace", code: "Backspace", keyCode: 8, which: 8, preventDefault: function() {}});
    });
    t.addEventListener("input", function() {
      var d = t.value;
      t.value = "";
      if (!d) return;
      var n = lengthBytesUTF8(d) + 1, p = _malloc(n);
      stringToUTF8(d, p, n);
      _csl_text_input(p);
      _free(p);
    });
  }
  var focused = document.activeElement;
  if (on) {
    t.style.left = (c.offsetLeft + x) + "px";
    t.style.top = (c.offsetTop + y) + "px";
    if (focused === c) t.focus({preventScroll: true});
  } else if (focused === t) {
    c.focus({preventScroll: true});
  }
});

// SDL's EGL layer takes eglGetProcAddress by address, and Emscripten's own version of it names
// every WebGL entry point of its GL library, which puts all of them (about 45 KB of JS, more than
// the app uses) into cspacelab.js. SDL only ever asks it for a few: those are given here, the
// rest (EGL extensions it may do without) as null, as a driver that lacks them answers.
extern "C" __eglMustCastToProperFunctionPointerType eglGetProcAddress(const char* name) {
  using Proc = __eglMustCastToProperFunctionPointerType;
  static const struct {
    const char* name;
    Proc proc;
  } kKnown[] = {
      {"glGetString", reinterpret_cast<Proc>(&glGetString)},
      {"glGetStringi", reinterpret_cast<Proc>(&glGetStringi)},
      {"glGetIntegerv", reinterpret_cast<Proc>(&glGetIntegerv)},
      {"glGetError", reinterpret_cast<Proc>(&glGetError)},
      {"glBindFramebuffer", reinterpret_cast<Proc>(&glBindFramebuffer)},
      {"glGetFramebufferAttachmentParameteriv", reinterpret_cast<Proc>(&glGetFramebufferAttachmentParameteriv)},
  };
  for (const auto& k : kKnown)
    if (name && std::strcmp(name, k.name) == 0) return k.proc;
  return nullptr;
}
#endif

/// Text for the field that has the keyboard (from the page: see csl_text_field_js). It joins SDL's
/// queue behind the key presses SDL has queued from the canvas: put straight into ImGui's, a
/// character typed after them came before them whenever a frame was slow ("³×R  S¹" for
/// "R³ × S¹": the × and ³ arrive this way, the R and the spaces as key presses).
extern "C" EMSCRIPTEN_KEEPALIVE_IF_WEB void csl_text_input(const char* utf8) {
  if (!utf8) return;
  const std::size_t n = std::strlen(utf8);
  for (std::size_t i = 0; i < n;) {
    // At most the event's 31 bytes, cut between characters, never inside one.
    std::size_t j = std::min(n, i + SDL_TEXTINPUTEVENT_TEXT_SIZE - 1);
    while (j < n && j > i + 1 && (static_cast<unsigned char>(utf8[j]) & 0xC0) == 0x80) --j;
    SDL_Event e{};
    e.type = SDL_TEXTINPUT;
    std::memcpy(e.text.text, utf8 + i, j - i);
    SDL_PushEvent(&e);
    i = j;
  }
}

namespace csl::app {

bool Platform::init(const PlatformOptions& options) {
  max_frames_ = options.max_frames;
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
    std::fprintf(stderr, "SDL_Init failed: %s\n", SDL_GetError());
    return false;
  }
#ifdef __EMSCRIPTEN__
  // WebGL2 is OpenGL ES 3.0.
  const char* glsl_version = "#version 300 es";
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
  // Keys go to the canvas, not the whole page: the page around an embedded lab keeps its keys.
  SDL_SetHint(SDL_HINT_EMSCRIPTEN_KEYBOARD_ELEMENT, "#canvas");
#else
  const char* glsl_version = "#version 130";
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 2);
#endif
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  // Multisampling is not needed: ImGui anti-aliases its own geometry.
  const auto flags = static_cast<SDL_WindowFlags>(SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE |
                                                  SDL_WINDOW_ALLOW_HIGHDPI);
  window_ = SDL_CreateWindow(options.title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             options.width, options.height, flags);
  if (!window_) {
    std::fprintf(stderr, "SDL_CreateWindow failed: %s\n", SDL_GetError());
    return false;
  }
  gl_context_ = SDL_GL_CreateContext(window_);
  if (!gl_context_) {
    std::fprintf(stderr, "Could not create an OpenGL/WebGL2 context: %s\n", SDL_GetError());
    return false;
  }
  SDL_GL_MakeCurrent(window_, gl_context_);
  SDL_GL_SetSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // layout is the app's, not a file's (and the web has no files)
  io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
#ifdef __EMSCRIPTEN__
  // A device whose only pointer is a finger has touch-sized targets from the start (not only
  // after its first touch).
  // (The unused 0: EM_ASM_INT with no argument at all needs a GNU extension of variadic macros.)
  if (EM_ASM_INT({ return matchMedia("(pointer: coarse)").matches && !matchMedia("(any-pointer: fine)").matches ? 1 : 0; }, 0))
    input::set_touch(true);
#endif
  ImGui_ImplSDL2_InitForOpenGL(window_, gl_context_);
  ImGui_ImplOpenGL3_Init(glsl_version);
  return true;
}

void Platform::sync_canvas_size() {
#ifdef __EMSCRIPTEN__
  // The page sizes the canvas with CSS (it may sit in any container); follow it, so that the
  // backing store is always CSS size x devicePixelRatio and nothing is blurred.
  double css_w = 0, css_h = 0;
  emscripten_get_element_css_size("#canvas", &css_w, &css_h);
  int w = 0, h = 0;
  SDL_GetWindowSize(window_, &w, &h);
  const int want_w = css_w < 1 ? 1 : static_cast<int>(css_w);
  const int want_h = css_h < 1 ? 1 : static_cast<int>(css_h);
  const auto dpr = static_cast<float>(emscripten_get_device_pixel_ratio());
  if (want_w != w || want_h != h || dpr != pixel_ratio_) SDL_SetWindowSize(window_, want_w, want_h);
#endif
}

void Platform::update_pixel_ratio() {
  int w = 0, h = 0, dw = 0, dh = 0;
  SDL_GetWindowSize(window_, &w, &h);
  SDL_GL_GetDrawableSize(window_, &dw, &dh);
  const float ratio = w > 0 ? static_cast<float>(dw) / static_cast<float>(w) : 1.0f;
  if (ratio <= 0.0f || ratio == pixel_ratio_) return;
  pixel_ratio_ = ratio;
  // Rasterise glyphs at device resolution and scale them back: crisp text on HiDPI screens.
  build_fonts(ratio);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}

namespace {
double now_ms() {
  return 1000.0 * static_cast<double>(SDL_GetPerformanceCounter()) / static_cast<double>(SDL_GetPerformanceFrequency());
}

bool is_modifier(SDL_Scancode key) {
  switch (key) {
    case SDL_SCANCODE_LCTRL: case SDL_SCANCODE_RCTRL: case SDL_SCANCODE_LSHIFT: case SDL_SCANCODE_RSHIFT:
    case SDL_SCANCODE_LALT: case SDL_SCANCODE_RALT: case SDL_SCANCODE_LGUI: case SDL_SCANCODE_RGUI:
      return true;
    default:
      return false;
  }
}

// ImGui 1.86's SDL backend sets io.KeyCtrl and the others from SDL_GetModState() when it handles
// a key: the state after every event SDL has queued, which within one frame can be past the key
// (Ctrl released just after Z turned Ctrl+Z into a plain Z). Each key event carries the
// modifiers of its own moment; those are the ones that count.
void process(const SDL_Event& event) {
  ImGui_ImplSDL2_ProcessEvent(&event);
  if (event.type != SDL_KEYDOWN && event.type != SDL_KEYUP) return;
  ImGuiIO& io = ImGui::GetIO();
  const unsigned mod = event.key.keysym.mod;
  io.KeyShift = (mod & KMOD_SHIFT) != 0;
  io.KeyCtrl = (mod & KMOD_CTRL) != 0;
  io.KeyAlt = (mod & KMOD_ALT) != 0;
  io.KeySuper = (mod & KMOD_GUI) != 0;
}

void summarise(const std::array<double, 120>& values, std::size_t count, double& mean, double& p95, double& max) {
  std::array<double, 120> sorted = values;
  std::sort(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(count));
  double sum = 0;
  for (std::size_t i = 0; i < count; ++i) sum += sorted[i];
  mean = count ? sum / static_cast<double>(count) : 0.0;
  p95 = count ? sorted[std::min(count - 1, count * 95 / 100)] : 0.0;
  max = count ? sorted[count - 1] : 0.0;
}
}  // namespace

void Platform::frame_once() {
  const double start = now_ms();
  // Releases held back from the last frame first, so that frame saw the keys down.
  std::vector<SDL_Event> pending;
  pending.swap(deferred_);
  for (const SDL_Event& e : pending) process(e);
  std::vector<SDL_Scancode> pressed_now;
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    if (event.type == SDL_KEYDOWN) pressed_now.push_back(event.key.keysym.scancode);
    // ImGui 1.86 sees one state a frame, not a sequence: a key released in the frame that
    // pressed it would not count as pressed, and a modifier released after a key would not count
    // as held with it (Ctrl+Z with both released at once). Such a release waits a frame, and so
    // does everything after it, in order (a later key would set the modifiers of its own moment).
    if (event.type == SDL_KEYUP) {
      const SDL_Scancode key = event.key.keysym.scancode;
      const bool pressed = std::find(pressed_now.begin(), pressed_now.end(), key) != pressed_now.end();
      if (pressed || (is_modifier(key) && !pressed_now.empty())) {
        deferred_.push_back(event);
        break;  // the rest stays in SDL's queue for the next frame
      }
    }
    track_pointer(event);
    process(event);
    if (event.type == SDL_QUIT) quit_ = true;
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE &&
        event.window.windowID == SDL_GetWindowID(window_))
      quit_ = true;
  }
  sync_canvas_size();
  update_pixel_ratio();

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  update_gesture();
  hold_mouse_during_gesture();
  ImGui::NewFrame();
  frame_();
  ImGui::Render();
#ifdef __EMSCRIPTEN__
  // While a field has the keyboard, every frame (a click on the canvas takes the focus back);
  // once when it lets go.
  if (ImGui::GetIO().WantTextInput || text_mode_) {
    text_mode_ = ImGui::GetIO().WantTextInput;
    const ImVec2 at = ImGui::GetCurrentContext()->PlatformImePos;
    csl_text_field_js(text_mode_ ? 1 : 0, at.x < 1e6f ? at.x : 0.0f, at.y < 1e6f ? at.y : 0.0f);
  }
#endif
  const double ui_done = now_ms();

  const ImGuiIO& io = ImGui::GetIO();
  glViewport(0, 0, static_cast<int>(io.DisplaySize.x * io.DisplayFramebufferScale.x),
             static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y));
  const ImVec4 clear = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];  // behind everything: the look's panel
  glClearColor(clear.x, clear.y, clear.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  SDL_GL_SwapWindow(window_);
  const std::size_t slot = static_cast<std::size_t>(frames_) % kTimed;
  cpu_ms_[slot] = now_ms() - start;
  ui_ms_[slot] = ui_done - start;
  stats_.vertices = ImGui::GetDrawData()->TotalVtxCount;
  interval_ms_[slot] = last_start_ < 0 ? 0.0 : start - last_start_;
  last_start_ = start;
  ++frames_;
  const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(frames_), kTimed);
  summarise(interval_ms_, count, stats_.mean_interval_ms, stats_.p95_interval_ms, stats_.max_interval_ms);
  summarise(cpu_ms_, count, stats_.mean_cpu_ms, stats_.p95_cpu_ms, stats_.max_cpu_ms);
  summarise(ui_ms_, count, stats_.mean_ui_ms, stats_.p95_ui_ms, stats_.max_ui_ms);
  if (max_frames_ >= 0 && frames_ >= max_frames_) quit_ = true;
}

void Platform::track_pointer(const SDL_Event& event) {
  int w = 0, h = 0;
  SDL_GetWindowSize(window_, &w, &h);
  switch (event.type) {
    case SDL_FINGERDOWN:
    case SDL_FINGERMOTION: {
      input::set_touch(true);
      // SDL gives a finger's place as a fraction of the window.
      const ImVec2 at(event.tfinger.x * static_cast<float>(w), event.tfinger.y * static_cast<float>(h));
      const long long id = static_cast<long long>(event.tfinger.fingerId);
      if (event.type == SDL_FINGERDOWN && fingers_.empty()) {
        first_press_ = at;
        first_finger_ = id;
        input::set_finger_travel(0.0f);
      }
      fingers_[id] = at;
      if (fingers_.size() > 1) input::set_finger_travel(std::numeric_limits<float>::infinity());
      else if (id == first_finger_)
        input::set_finger_travel(std::max(input::finger_travel(), std::hypot(at.x - first_press_.x, at.y - first_press_.y)));
      break;
    }
    case SDL_FINGERUP:
      fingers_.erase(static_cast<long long>(event.tfinger.fingerId));
      break;
    case SDL_MOUSEMOTION:
      if (event.motion.which != SDL_TOUCH_MOUSEID) input::set_touch(false);
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.which != SDL_TOUCH_MOUSEID) input::set_touch(false);
      break;
    default:
      break;
  }
}

void Platform::update_gesture() {
  input::Pinch pinch;
  if (fingers_.size() >= 2) {
    const ImVec2 a = fingers_.begin()->second, b = std::next(fingers_.begin())->second;
    const ImVec2 center(0.5f * (a.x + b.x), 0.5f * (a.y + b.y));
    const float spread = std::max(1.0f, std::hypot(a.x - b.x, a.y - b.y));
    pinch.active = true;
    pinch.center = center;
    if (pinching_) {  // (a pinch's first frame only sets where it starts from)
      pinch.scale = spread / last_spread_;
      pinch.pan = ImVec2(center.x - last_center_.x, center.y - last_center_.y);
    }
    pinching_ = true;
    if (!gesture_) gesture_frames_ = 0;
    gesture_ = true;
    last_center_ = center;
    last_spread_ = spread;
  } else {
    pinching_ = false;
    if (fingers_.empty()) gesture_ = false;
  }
  if (gesture_) ++gesture_frames_;
  input::set_pinch(pinch);
}

void Platform::hold_mouse_during_gesture() {
  if (!gesture_) return;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = first_press_;
  // Its first frame keeps the button down at the first press, so a drag that had begun ends
  // where it started; after that the button is up until every finger has lifted.
  if (gesture_frames_ > 1) io.MouseDown[0] = false;
}

void Platform::frame_trampoline(void* self) { static_cast<Platform*>(self)->frame_once(); }

void Platform::run(std::function<void()> frame) {
  frame_ = std::move(frame);
#ifdef __EMSCRIPTEN__
  // The browser calls us once per animation frame; this call does not return.
  emscripten_set_main_loop_arg(&Platform::frame_trampoline, this, 0, true);
#else
  while (!quit_) frame_once();
#endif
}

void Platform::shutdown() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
  SDL_GL_DeleteContext(gl_context_);
  SDL_DestroyWindow(window_);
  SDL_Quit();
}

}  // namespace csl::app
