#pragma once
// The assignment mode: an instructor's assignment file (core/teaching/assignment.hpp) opened in
// the lab, usually by the page's LMS layer through the API (assignment_open with the LMS's
// learner id and suspend data). A card at the top of the side panel (the compact layout's
// Controls tab) lists the items with their status, the progress and the score so far, and the
// current item: an exercise with its answer field and Check, a task with "Check my lab", an
// explore item with "Open in the lab"; Previous, Next, Submit; after submission a review of
// every item. What is recorded, graded and saved is core's (assignment_session.hpp): the CLI's
// `cspacelab assignment grade` gives the same grade for the same answers.
//
// Every change (open, answer, go, submit, close) is announced to the page as a DOM event
// "cspacelab:assignment" on the lab's root element, detail: the assignment_state (null after
// close), so that the LMS layer reports without polling.
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <set>
#include <string>

#include "app/shell/js_api.hpp"
#include "core/teaching/assignment_session.hpp"

namespace csl::app {

class AssignmentPanel {
 public:
  /// `show(lesson, setup, preset, view)`: shows `lesson`, with setup {scene?, params?} put in if
  /// `preset`, as far as the instructor's locks allow; `view`: the compact layout turns to its
  /// View tab. Returns "" or why the lab could not show all of it (a lock). Never throws.
  using Show = std::function<std::string(const std::string&, const nlohmann::json&, bool preset, bool view)>;
  /// `state_of(lesson)`: the lesson's state() as the API answers it; throws ApiError if the
  /// lesson is not open or still working.
  using StateOf = std::function<nlohmann::json(const std::string&)>;
  AssignmentPanel(Show show, StateOf state_of);

  /// assignment_validate, assignment_open, assignment_state, assignment_go, assignment_answer, assignment_submit,
  /// assignment_close.
  void register_api(JsApi& api);
  /// The card, above the lesson's panel, while an assignment is open.
  void card();
  bool active() const { return session_.has_value(); }

 private:
  nlohmann::json state_json() const;
  // Each throws ApiError, changing nothing, for what it refuses.
  void open(const nlohmann::json& args);
  void go(std::size_t index);
  nlohmann::json answer(std::size_t index, const std::optional<std::string>& text);
  void submit();
  std::size_t index_arg(const nlohmann::json& args) const;
  // The card's buttons: `action` run, what it refuses said in the card (note_).
  void act(const std::function<void()>& action);
  // Goes to item `index` from the card (an explore item is then viewed).
  void visit(std::size_t index);
  // Tells the page (the DOM event) and keeps the answer field in step with the item.
  void changed();
  void item_list();
  void current_item();
  void review();
  void navigation();
  void submit_confirmation();

  Show show_;
  StateOf state_of_;
  std::optional<AssignmentSession> session_;
  nlohmann::json state_;  // assignment_session_json(*session_) as of the last change
  std::set<std::size_t> preset_;  // items whose lesson got the item's setup this session
  std::string note_;              // why the lab could not show the item as written, or an error
  // The current exercise's answer field: room for the longest answer the core records (one set
  // through the API or resumed from suspend data), so that a re-check never records it cut.
  char answer_[kMaxAnswerText + 1] = "";
  std::size_t field_item_ = static_cast<std::size_t>(-1);  // the item answer_ belongs to
  bool focus_answer_ = false;
  bool want_confirm_ = false;
};

}  // namespace csl::app
