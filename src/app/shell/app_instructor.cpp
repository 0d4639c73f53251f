// The app's side of what an instructor fixes and hides (a link's lock=, hide=, reveal=; see
// instructor.hpp and core/teaching/restrictions.hpp): the API's restrict and restrictions, the
// scene and parameters a locked lesson is held to, and the checks the API's edits pass.
//
// A lock holds each lesson to its scene and parameters as they were when the lock was set
// (the link's, once the page applied it), or as a lesson opened later began: a restore of
// saved or previous work, or File > Reset, gets those back for the locked parts and keeps the
// rest (the step, the parameters not locked). The student's own edits are refused where they
// start: the editor, the panel's widgets, the API's set_scene, undo, redo and set_params.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "app/shell/app.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/theme.hpp"
#include "core/teaching/restrictions.hpp"
#include "imgui.h"

namespace csl::app {

using json = nlohmann::json;

namespace {

bool contains(const std::vector<std::string>& list, const std::string& key) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

std::string words_arg(const json& args, const char* key) {
  if (!args.contains(key) || args[key].is_null()) return "";
  const json& v = args[key];
  if (!v.is_string() || v.get<std::string>().size() > 256)
    throw ApiError(std::string(key) + ": comma-separated words (at most 256 characters)");
  return v.get<std::string>();
}

}  // namespace

Lesson& App::instance(const std::string& id) {
  auto& slot = instances_[id];
  if (!slot) {
    slot = find_lesson(id)->create();
    if (instructor::restrictions().any_lock() && !pins_.count(id)) pin(id, *slot);
  }
  return *slot;
}

void App::pin(const std::string& id, const Lesson& lesson) {
  Lesson& l = const_cast<Lesson&>(lesson);  // scene() is not const; nothing is changed
  json& pin = pins_[id] = json::object();
  pin["scene"] = l.scene() ? scene_to_json(*l.scene()) : json(nullptr);
  pin["params"] = lesson.params();
  pin["scene_params"] = lesson.scene_params();
}

json App::pinned(const std::string& id, json snapshot) const {
  const Restrictions& r = instructor::restrictions();
  auto it = pins_.find(id);
  if (!r.any_lock() || it == pins_.end()) return snapshot;
  const json& pin = it->second;
  if (r.lock_scene && !pin["scene"].is_null()) snapshot["scene"] = pin["scene"];
  json params = snapshot.contains("params") && snapshot["params"].is_object() ? snapshot["params"] : json::object();
  for (auto p = pin["params"].begin(); p != pin["params"].end(); ++p) {
    const bool scene_part = r.lock_scene && contains(pin["scene_params"].get<std::vector<std::string>>(), p.key());
    if (r.param_locked(p.key()) || scene_part) params[p.key()] = p.value();
  }
  if (!params.empty()) snapshot["params"] = params;
  return snapshot;
}

void App::check_params_allowed(const Lesson& lesson, const json& params) const {
  if (!params.is_object()) return;  // the lesson says what is wrong
  const std::vector<std::string> scene_keys = lesson.scene_params();
  for (auto it = params.begin(); it != params.end(); ++it) {
    if (instructor::param_locked(it.key())) throw ApiError(instructor::param_refusal(it.key()));
    if (instructor::scene_locked() && contains(scene_keys, it.key()))
      throw ApiError(it.key() + " is part of the scene, which is fixed by your instructor (lock=scene)");
  }
}

void App::hold_locked_params(const json& before) {
  const Restrictions& r = instructor::restrictions();
  if (!r.lock_params && r.locked_params.empty() && !r.lock_scene) return;
  // Only what the student's input changed: an animation may move a parameter by itself (the
  // torus lesson's loops walk the arm's q), which is the lesson showing, not the student editing.
  const ImGuiIO& io = ImGui::GetIO();
  bool input = ImGui::IsAnyMouseDown() || io.InputQueueCharacters.Size > 0;
  for (bool down : io.KeysDown) input = input || down;
  if (!input) return;
  const json after = lesson_->params();
  const std::vector<std::string> scene_keys = lesson_->scene_params();
  json back = json::object();
  std::string first;
  for (auto it = after.begin(); it != after.end(); ++it) {
    const bool held = r.param_locked(it.key()) || (r.lock_scene && contains(scene_keys, it.key()));
    if (!held || !before.contains(it.key()) || before[it.key()] == it.value()) continue;
    back[it.key()] = before[it.key()];
    if (first.empty()) first = it.key();
  }
  if (back.empty()) return;
  try {
    lesson_->set_params(back);
  } catch (const std::exception&) {
    // the value it had a frame ago: taken before, so taken now
  }
  ctx_.notify(r.param_locked(first) ? instructor::param_refusal(first) + ": it stays as it is."
                                    : instructor::scene_refusal(),
              4.0);
}

void App::instructor_note() {
  const Restrictions& r = instructor::restrictions();
  std::string fixed;  // "the scene, the parameters, the lesson"
  const auto add = [&fixed](const std::string& what) { fixed += (fixed.empty() ? "" : ", ") + what; };
  if (r.lock_scene && lesson_->scene()) add("the scene");
  if (r.lock_params) add("the parameters");
  const json params = r.locked_params.empty() ? json() : lesson_->params();
  for (const std::string& p : r.locked_params)
    if (params.contains(p)) add(p);
  if (r.lock_lesson) add("the lesson");
  std::string hidden;
  for (const HideableAnswer* a : instructor::hidden_answers(lesson_id_))
    hidden += (hidden.empty() ? "" : ", ") + std::string(a->name);
  if (fixed.empty() && hidden.empty()) return;
  const std::string text = (fixed.empty() ? "" : "Fixed by your instructor: " + fixed + ". ") +
                           (hidden.empty() ? "" : "Hidden: " + hidden + ".");
  ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(theme::kTextKey));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
  ImGui::Spacing();
}

json App::restrictions_json() const {
  // (Assignments, and no more than the page and tests use: the wasm's budget is tight.)
  const Restrictions& r = instructor::restrictions();
  json out = json::object();
  out["lock"] = r.lock_text();
  out["hide"] = r.hide_text();
  out["reveal"] = r.reveal_text();
  out["scene"] = r.lock_scene;
  json& now = out["hidden_now"] = json::array();
  for (const HideableAnswer* a : instructor::hidden_answers(lesson_id_)) now.push_back(std::string(a->name));
  out["locked_lesson"] = instructor::locked_lesson().empty() ? json(nullptr) : json(instructor::locked_lesson());
  return out;
}

void App::register_instructor_api() {
  JsApi& api = js_api();
  api.add("restrict", "a link's {lock?, hide?, reveal?, lesson?} (docs/web.md); bad words are left out, named in problems",
          [this](const json& args) {
            // (An unknown lesson has no parameters or answers: its words are all refused.)
            const std::string lesson = args.contains("lesson") ? words_arg(args, "lesson") : lesson_id_;
            std::vector<std::string> problems;
            const Restrictions r =
                parse_restrictions(words_arg(args, "lock"), words_arg(args, "hide"), words_arg(args, "reveal"), lesson, &problems);
            instructor::set(r, lesson_id_);
            // What each open lesson has now is what the lock holds it to.
            pins_.clear();
            if (r.any_lock())
              for (auto& [id, l] : instances_)
                if (l) pin(id, *l);
            // The event log again, as hidden answers now allow (a path's length leaves its line).
            ctx_.log.clear();
            lesson_->on_show();
            json out = restrictions_json();
            out["problems"] = problems;
            return out;
          });
}

}  // namespace csl::app
