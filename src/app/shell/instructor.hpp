#pragma once
// What the instructor fixed and hid in this lab (a link's lock=, hide= and reveal=, or a page's
// data-lab: core/teaching/restrictions.hpp reads the words), as the app's code asks it: may
// the scene be edited, may this parameter change, may the student leave this lesson, is this
// answer hidden now. The page sets it through the API's "restrict" (App::register_api); the
// lessons, the scene editor and the shell read it here. Nothing here is security: a student
// may edit the address. It keeps an exercise an exercise.
#include <string>
#include <string_view>
#include <vector>

#include "core/teaching/restrictions.hpp"

namespace csl::app::instructor {

/// "fixed by your instructor", "hidden by your instructor": the words every surface uses.
extern const char* const kFixed;
extern const char* const kHidden;

const Restrictions& restrictions();
/// The lesson lock=lesson keeps the lab on ("" without that lock).
const std::string& locked_lesson();
/// Replaces what is in force; `lesson`: the lesson on screen (kept by lock=lesson).
void set(const Restrictions& r, const std::string& lesson);

bool scene_locked();
bool param_locked(std::string_view key);
/// Whether the student may switch to lesson `id`.
bool lesson_allowed(const std::string& id);

/// An exercise of homework problem `id` was answered right (reveal=after-answer).
void solved(const std::string& problem);
/// Whether answer `name` is hidden now (in whichever lesson shows it).
bool hidden(const char* name);
/// The answers of `lesson` hidden now.
std::vector<const HideableAnswer*> hidden_answers(const std::string& lesson);

/// One line each, for notices and API errors.
std::string scene_refusal();                      ///< "The scene is fixed by your instructor (lock=scene): ..."
std::string param_refusal(const std::string& key);  ///< "grid_n is fixed by your instructor (lock=...)"
std::string lesson_refusal();

/// In place of a hidden number, in the panel: "<what>: hidden by your instructor" (dimmed).
void hidden_line(const char* what);
/// A dimmed, wrapped line (why something is disabled).
void dim_line(const std::string& text);

/// Around the widget that sets parameter `key`: drawn disabled while it is locked, with a
/// tooltip saying so (the last widget in the scope carries it). `scene_part`: the parameter is
/// the scene's too (Lesson::scene_params), so a scene lock fixes it as well.
class FixedParam {
 public:
  explicit FixedParam(const char* key, bool scene_part = false);
  ~FixedParam();
  FixedParam(const FixedParam&) = delete;
  FixedParam& operator=(const FixedParam&) = delete;
  bool locked() const { return locked_; }

 private:
  bool locked_;
};

/// Around scene-changing widgets that are not the editor's (a lesson's robot choice, its
/// example scenes): disabled while the scene is locked, with the tooltip.
class FixedScene {
 public:
  FixedScene();
  ~FixedScene();
  FixedScene(const FixedScene&) = delete;
  FixedScene& operator=(const FixedScene&) = delete;

 private:
  bool locked_;
};

}  // namespace csl::app::instructor
