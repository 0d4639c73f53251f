#include "app/shell/instructor.hpp"

#include <algorithm>

#include "imgui.h"

namespace csl::app::instructor {

const char* const kFixed = "fixed by your instructor";
const char* const kHidden = "hidden by your instructor";

namespace {
struct State {
  Restrictions r;
  std::string lesson;
  std::vector<std::string> solved;
};
State& state() {
  static State s;
  return s;
}

void fixed_tooltip() {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", kFixed);
}
}  // namespace

const Restrictions& restrictions() { return state().r; }
const std::string& locked_lesson() {
  static const std::string none;
  return state().r.lock_lesson ? state().lesson : none;
}

void set(const Restrictions& r, const std::string& lesson) {
  state().r = r;
  state().lesson = lesson;
}

bool scene_locked() { return state().r.lock_scene; }
bool param_locked(std::string_view key) { return state().r.param_locked(key); }
bool lesson_allowed(const std::string& id) { return !state().r.lock_lesson || id == state().lesson; }

void solved(const std::string& problem) {
  std::vector<std::string>& s = state().solved;
  if (std::find(s.begin(), s.end(), problem) == s.end()) s.push_back(problem);
}

bool hidden(const char* name) {
  for (const HideableAnswer& a : hideable_answers())
    if (a.name == name && answer_hidden(state().r, a, state().solved)) return true;
  return false;
}

std::vector<const HideableAnswer*> hidden_answers(const std::string& lesson) {
  std::vector<const HideableAnswer*> out;
  for (const HideableAnswer* a : answers_of(lesson))
    if (answer_hidden(state().r, *a, state().solved)) out.push_back(a);
  return out;
}

std::string scene_refusal() {
  return "The scene is fixed by your instructor (lock=scene): it cannot be edited in this lab.";
}
std::string param_refusal(const std::string& key) {
  return key + " is fixed by your instructor (lock=" + (state().r.lock_params ? "params" : key) + ")";
}
std::string lesson_refusal() {
  return "The lesson is fixed by your instructor (lock=lesson).";
}

void hidden_line(const char* what) { dim_line(std::string(what) + ": " + kHidden); }

void dim_line(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

FixedParam::FixedParam(const char* key, bool scene_part)
    : locked_(param_locked(key) || (scene_part && scene_locked())) {
  if (locked_) ImGui::BeginDisabled();
}
FixedParam::~FixedParam() {
  if (!locked_) return;
  ImGui::EndDisabled();
  fixed_tooltip();
}

FixedScene::FixedScene() : locked_(scene_locked()) {
  if (locked_) ImGui::BeginDisabled();
}
FixedScene::~FixedScene() {
  if (!locked_) return;
  ImGui::EndDisabled();
  fixed_tooltip();
}

}  // namespace csl::app::instructor
