#include "app/shell/web_bridge.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <map>

#include "app/shell/bundled_scenes.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "core/base/version.hpp"
#include "imgui.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The page's handler runs later (a timer), never inside this frame: it may restore lessons.
EM_JS(void, csl_page_action_js, (const char* name), {
  var handler = Module["cslPageAction"];
  if (typeof handler === "function") handler(UTF8ToString(name));
});
#endif

namespace csl::app::web {

using json = nlohmann::json;

namespace {

PageState& state() {
  static PageState s;
  return s;
}

bool want_reset = false;  // the File menu asked for the confirmation (opened outside the menu)

// Where this frame's page controls are (logical = CSS pixels of the canvas), by name: page_state
// reports them, so a test (or a guided tour) can press the real buttons.
std::map<std::string, std::array<float, 4>>& rects() {
  static std::map<std::string, std::array<float, 4>> r;
  return r;
}
void record(const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects()[name] = {a.x, a.y, b.x, b.y};
}

// Width of a button with this label in the current style.
float button_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2.0f;
}

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// The look that the choice and the browser's preferences give.
theme::Look look_of(const PageState& s) {
  theme::Look look;
  look.dark = s.scheme == "dark" || (s.scheme == "system" && s.system_dark);
  look.high_contrast = s.contrast == "high" || (s.contrast == "system" && s.system_high_contrast);
  return look;
}

// Display: light, dark or the system's; high contrast or not. The page remembers the choice.
void display_menu() {
  PageState& s = state();
  if (!ImGui::BeginMenu("Display")) return;
  const auto choice = [&](const char* label, std::string& field, const char* value) {
    if (ImGui::MenuItem(label, nullptr, field == value)) {
      field = value;
      theme::request_look(look_of(s));
      page_action("look");
    }
    record(std::string(&field == &s.scheme ? "scheme-" : "contrast-") + value);
  };
  ImGui::TextDisabled("Colours");
  choice("Like the system", s.scheme, "system");
  choice("Light", s.scheme, "light");
  choice("Dark", s.scheme, "dark");
  ImGui::Separator();
  ImGui::TextDisabled("Contrast");
  choice("Like the system##contrast", s.contrast, "system");
  choice("Normal", s.contrast, "normal");
  choice("High", s.contrast, "high");
  ImGui::EndMenu();
}

void file_menu(const std::string& lesson_name) {
  const PageState& s = state();
  if (ImGui::MenuItem("Import scene (JSON)...")) page_action("import");
  record("import");
  tooltip("load a scene file into this lesson (or drop the file on the lab)");
  if (ImGui::MenuItem("Export scene (JSON)")) page_action("export-scene");
  record("export-scene");
  if (ImGui::MenuItem("Export view (PNG)")) page_action("export-png");
  record("export-png");
  if (ImGui::MenuItem("Export roadmap / path (JSON)")) page_action("export-state");
  record("export-state");
  tooltip("the lesson's state at this step: vertices, edges and path of a roadmap, or an edge check's trace");
  ImGui::Separator();
  // The instructor's Author view (web/lab-author.js): an assignment from this lab's states.
  if (!s.minimal) {
    if (ImGui::MenuItem("Author an assignment...")) page_action("author");
    record("author");
    tooltip("build an assignment (exercises, lab states, tasks), preview it as a student, export it and its SCORM zips");
  }
  if (s.minimal && ImGui::MenuItem("Open in the full lab")) page_action("open-full");
  if (ImGui::MenuItem(("Reset " + lesson_name + " to its default...").c_str())) want_reset = true;
  record("reset");
  if (!s.previous.empty() && ImGui::MenuItem("Restore my previous work")) page_action("restore-previous");
  if (!s.history.empty()) {
    // Every replaced state the page kept (links, resets, work that could not be restored, other
    // tabs): any of them comes back, and what is on screen goes into the list first.
    ImGui::Separator();
    ImGui::TextDisabled("Previous work, newest first (click to restore):");
    for (std::size_t i = 0; i < s.history.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));  // labels may repeat
      const std::string action = "restore-history:" + std::to_string(i);
      if (ImGui::MenuItem(s.history[i].c_str())) page_action(action.c_str());
      record("history-" + std::to_string(i));
      ImGui::PopID();
    }
  }
  ImGui::Separator();
  display_menu();
  record("display");
  ImGui::Separator();
  ImGui::TextDisabled("C-Space Lab v%s", kVersion);
}

void reset_confirmation(const std::string& lesson_name) {
  if (want_reset) {
    ImGui::OpenPopup("Reset lesson?");
    want_reset = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(320, 0), ImVec2(std::max(320.0f, vp->WorkSize.x * 0.8f), FLT_MAX));
  if (!ImGui::BeginPopupModal("Reset lesson?", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
    return;
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 420.0f);
  ImGui::TextWrapped("Reset %s to its default scene and parameters?", lesson_name.c_str());
  ImGui::TextWrapped("What you have now is kept: \"Restore my previous work\" brings it back.");
  ImGui::PopTextWrapPos();
  ImGui::Spacing();
  if (ImGui::Button("Reset")) {
    page_action("reset");
    ImGui::CloseCurrentPopup();
  }
  record("reset-confirm");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  record("reset-cancel");
  if (cancel || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

// page_state's history: [{label}], checked whole before anything changes. A label is shown as
// a menu item's text, where ImGui would read "##" as the start of a hidden id: it is spelt "# #".
std::vector<std::string> history_labels(const json& value) {
  const std::string what = "history: at most " + std::to_string(kMaxHistory) + " entries {label: a string of at most " +
                           std::to_string(kMaxHistoryLabel) + " characters}";
  if (!value.is_array() || value.size() > kMaxHistory) throw ApiError(what);
  std::vector<std::string> labels;
  for (const json& entry : value) {
    if (!entry.is_object() || entry.size() != 1 || !entry.contains("label") || !entry["label"].is_string())
      throw ApiError(what);
    std::string label = entry["label"].get<std::string>();
    if (label.size() > kMaxHistoryLabel) throw ApiError(what);
    for (std::size_t at = label.find("##"); at != std::string::npos; at = label.find("##", at + 2)) label.insert(at + 1, " ");
    labels.push_back(std::move(label));
  }
  return labels;
}

}  // namespace

const PageState& page() { return state(); }

void dismiss_welcome() {
  if (!state().welcome) return;
  state().welcome = false;
  page_action("welcome-seen");
}

void record_control(const char* name) { record(name); }

void begin_controls() { rects().clear(); }

void page_action(const char* name) {
#ifdef __EMSCRIPTEN__
  csl_page_action_js(name);
#else
  (void)name;
#endif
}

void register_api(JsApi& api, LabContext& ctx) {
  api.add("notify", "show a one-line notice in the app: {text, seconds?}", [&ctx](const json& args) {
    const json text = args.value("text", json());
    if (!text.is_string()) throw ApiError("text: a string");
    double seconds = 8.0;
    if (args.contains("seconds")) {
      const json& v = args["seconds"];
      if (!v.is_number() || v.get<double>() < 0.5 || v.get<double>() > 120.0) throw ApiError("seconds: a number in [0.5, 120]");
      seconds = v.get<double>();
    }
    std::string t = text.get<std::string>();
    if (t.size() > 600) t = t.substr(0, 597) + "...";  // a notice is a line or two, never a dump
    ctx.notify(t, seconds);
    return json(true);
  });
  api.add("page_state", "the page around the app: {attached?, minimal?, welcome?, reduced_motion?, previous?, history?: [{label}], scheme?: system|light|dark, contrast?: system|normal|high, system_dark?, system_high_contrast?}; also the look in use and where its buttons are (CSS px)", [](const json& args) {
    PageState next = state();
    for (auto it = args.begin(); it != args.end(); ++it) {
      if (it.key() == "attached" || it.key() == "minimal" || it.key() == "welcome" || it.key() == "reduced_motion" ||
          it.key() == "system_dark" || it.key() == "system_high_contrast") {
        if (!it->is_boolean()) throw ApiError(it.key() + ": true or false");
        (it.key() == "attached"    ? next.attached
         : it.key() == "minimal"   ? next.minimal
         : it.key() == "welcome"   ? next.welcome
         : it.key() == "system_dark" ? next.system_dark
         : it.key() == "system_high_contrast" ? next.system_high_contrast
                                   : next.reduced_motion) = it->get<bool>();
      } else if (it.key() == "scheme" || it.key() == "contrast") {
        const bool scheme = it.key() == "scheme";
        const std::string v = it->is_string() ? it->get<std::string>() : "";
        const bool ok = v == "system" || (scheme ? (v == "light" || v == "dark") : (v == "normal" || v == "high"));
        if (!ok) throw ApiError(scheme ? "scheme: system, light or dark" : "contrast: system, normal or high");
        (scheme ? next.scheme : next.contrast) = v;
      } else if (it.key() == "previous") {
        if (!it->is_string() || it->get<std::string>().size() > 200) throw ApiError("previous: a string of at most 200 characters");
        next.previous = it->get<std::string>();
      } else if (it.key() == "history") {
        next.history = history_labels(*it);
      } else {
        throw ApiError("unknown field \"" + it.key() +
                       "\" (attached, minimal, welcome, reduced_motion, previous, history, scheme, contrast, system_dark, system_high_contrast)");
      }
    }
    state() = next;
    const theme::Look look = look_of(next);
    theme::request_look(look);
    json buttons = json::object();
    for (const auto& [name, r] : rects()) buttons[name] = r;
    json history = json::array();
    for (const std::string& label : next.history) history.push_back({{"label", label}});
    return json{{"attached", next.attached}, {"minimal", next.minimal}, {"welcome", next.welcome},
                {"reduced_motion", next.reduced_motion}, {"previous", next.previous},
                {"history", history}, {"buttons", buttons}, {"scheme", next.scheme}, {"contrast", next.contrast},
                {"system_dark", next.system_dark}, {"system_high_contrast", next.system_high_contrast},
                {"look", {{"dark", look.dark}, {"high_contrast", look.high_contrast}}}};
  });
  api.add("bundled_scenes", "the bundled scenes by name (what ?scene=NAME loads)", [](const json&) {
    json out = json::object();
    for (const BundledScene& s : bundled_scenes()) out[s.name] = scene_to_json(scene_from_string(s.json));
    return out;
  });
}

namespace {
const char* const kRestore = "Restore my previous work";
const char* const kActions[] = {"Share", "Embed", "File"};
}  // namespace

float top_bar_actions_width() {
  const PageState& s = state();
  const ImGuiStyle& style = ImGui::GetStyle();
  if (!s.attached) return ImGui::CalcTextSize("v").x + ImGui::CalcTextSize(kVersion).x;
  float width = -style.ItemSpacing.x;
  for (const char* l : kActions) width += button_width(l) + style.ItemSpacing.x;
  if (!s.previous.empty()) width += button_width(kRestore) + style.ItemSpacing.x;
  return width;
}

void top_bar_actions(LabContext& ctx, const std::string& lesson_name) {
  const bool tall = ctx.tall_bar;  // ui::bar_button
  const PageState& s = state();
  if (!s.attached) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("v%s", kVersion);
    return;
  }
  const char* restore = kRestore;
  if (!s.previous.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Button, theme::vec4(theme::kRestoreButton));
    if (ui::bar_button(restore, tall)) page_action("restore-previous");
    record("restore-previous");
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("bring back %s (what you have now becomes the previous work)", s.previous.c_str());
    ImGui::SameLine();
  }
  if (ui::bar_button("Share", tall)) page_action("share");
  record("share");
  tooltip("a link to exactly this: lesson, scene, parameters, seed and step (copied to the clipboard)");
  ImGui::SameLine();
  if (ui::bar_button("Embed", tall)) page_action("embed");
  record("embed");
  tooltip("HTML to put this lab, as it is now, in a course page");
  ImGui::SameLine();
  if (ui::bar_button("File", tall)) ImGui::OpenPopup("##file-menu");
  record("file");
  tooltip("import, export, reset");
  if (ImGui::BeginPopup("##file-menu")) {
    file_menu(lesson_name);
    ImGui::EndPopup();
  }
  reset_confirmation(lesson_name);
}

}  // namespace csl::app::web
