#pragma once
// What an instructor fixes and hides in a lab: a link's (or a page's data-lab) `lock=`, `hide=`
// and `reveal=`, read the same way by the app (through the page) and by `cspacelab link`.
//
//   lock=scene,params          the scene cannot be edited, no parameter can be changed
//   lock=lesson,grid_n         the lesson menu stays on the link's lesson; grid_n is fixed
//   hide=answers               every lesson's answers (below) are hidden
//   hide=min_n,path_length     only these
//   reveal=after-answer        a hidden answer comes back once its homework problem's exercise
//                              was answered right in this visit (default: never)
//
// Each lesson's answers are listed once, here: the name a link uses, the homework problems it
// answers, and the fields of the lesson's state() (JSON pointers; "*" is every element of an
// array) that hold it; answer_descriptions.hpp says what each is in words. The app removes those fields from state() and
// leaves the answer out of its drawing, its description and its event log while it is hidden;
// the CLI and the tests read the same list.
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace csl {

// (Static data, as the lesson catalogue: no code to build it in the wasm.)
struct HideableAnswer {
  std::string_view name;    ///< as in hide= ("min_n")
  std::string_view lesson;  ///< the lesson that shows it ("collision")
  std::initializer_list<std::string_view> problems;  ///< the homework problems it answers ("P12"); none: never revealed by an answer
  std::initializer_list<std::string_view> fields;    ///< where state() holds it ("/min_grid", "/control_points/*/rho")
};

/// Every lesson's answers, lesson by lesson in the menu's order.
const std::vector<HideableAnswer>& hideable_answers();
/// The answers `lesson` can hide (none for an unknown lesson).
std::vector<const HideableAnswer*> answers_of(const std::string& lesson);

enum class Reveal { Never, AfterAnswer };

struct Restrictions {
  bool lock_scene = false;   ///< no edit of any lesson's scene
  bool lock_params = false;  ///< no change of any parameter
  bool lock_lesson = false;  ///< no other lesson than the one the lock was set in
  std::vector<std::string> locked_params;  ///< parameters fixed by name (in any lesson that has them)
  bool hide_all = false;                   ///< hide=answers
  std::vector<std::string> hidden;         ///< the answers hidden (names, each once; all of them for hide=answers)
  Reveal reveal = Reveal::Never;

  bool param_locked(std::string_view key) const;
  bool hides(std::string_view answer) const;
  bool any_lock() const { return lock_scene || lock_params || lock_lesson || !locked_params.empty(); }
  bool empty() const { return !any_lock() && hidden.empty(); }
  /// The words of a link again, canonical (what Share writes): "scene,params,grid_n", "answers"
  /// or "min_n,path_length", "never" or "after-answer". "" where nothing is set.
  std::string lock_text() const;
  std::string hide_text() const;
  std::string reveal_text() const;
};

/// Reads lock, hide and reveal (comma-separated words; "" sets nothing) for a link to `lesson`
/// ("": any lesson), whose parameters and answers those words may name. Without `problems`,
/// the first bad word throws std::invalid_argument with one line naming it and the words
/// allowed ("lock: \"foo\" is not scene, params, lesson or a parameter of collision (grid_n,
/// p, q)"). With it, each bad word is left out and its line added there: the rest applies.
Restrictions parse_restrictions(const std::string& lock, const std::string& hide, const std::string& reveal,
                                const std::string& lesson, std::vector<std::string>* problems = nullptr);

/// Whether `answer` is hidden now: hidden by `r`, and not revealed (reveal=after-answer and
/// one of its problems is in `solved`, the problems answered right in this visit).
bool answer_hidden(const Restrictions& r, const HideableAnswer& answer, const std::vector<std::string>& solved);

/// Removes every field of `answers` from `state` (a lesson's state()); a field that is not
/// there is skipped.
void strip_answer_fields(nlohmann::json& state, const std::vector<const HideableAnswer*>& answers);

}  // namespace csl
