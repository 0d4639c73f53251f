#include "app/shell/assignment_panel.hpp"

#include <cfloat>
#include <cstdio>
#include <stdexcept>

#include "app/shell/bundled_scenes.hpp"
#include "app/shell/card.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "core/base/text.hpp"
#include "imgui.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

// The page's listeners run once this call or frame is over (a microtask), never inside it: an
// LMS layer that answers by calling the API again finds the app between calls. The root is the
// lab's [data-lab] element (web/lab.js), the canvas's parent in a page without one.
EM_JS(void, csl_assignment_event_js, (const char* detail), {
  var canvas = Module["canvas"];
  var root = canvas && (canvas.closest("[data-lab]") || canvas.parentElement);
  if (!root) return;
  var state = JSON.parse(UTF8ToString(detail));
  queueMicrotask(function() {
    root.dispatchEvent(new CustomEvent("cspacelab:assignment", {detail: state, bubbles: true}));
  });
});
#endif

namespace csl::app {

using json = nlohmann::json;

namespace {

// Each status as the list shows it: a mark (the font's geometric shapes) and a word.
struct StatusLook {
  const char* mark;
  const char* word;
};
StatusLook status_look(const std::string& status) {
  if (status == "correct") return {"\xE2\x97\x8F", "right"};        // ●
  if (status == "incorrect") return {"\xE2\x8A\x98", "not right"};  // ⊘
  if (status == "viewed") return {"\xE2\x97\x8F", "viewed"};
  if (status == "answered") return {"\xE2\x97\x91", "unreadable"};  // ◑
  return {"\xE2\x97\x8B", "to do"};                                 // ○
}

std::string points_text(double v) { return significant(v, 6); }

}  // namespace

AssignmentPanel::AssignmentPanel(Show show, StateOf state_of) : show_(std::move(show)), state_of_(std::move(state_of)) {}

json AssignmentPanel::state_json() const {
  json out = state_;
  out["note"] = note_;
  return out;
}

void AssignmentPanel::changed() {
  // Graded once per change, not per frame: the card draws from this.
  state_ = session_ ? assignment_session_json(*session_) : json();
#ifdef __EMSCRIPTEN__
  csl_assignment_event_js(session_ ? state_json().dump(-1, ' ', false, json::error_handler_t::replace).c_str() : "null");
#endif
}

void AssignmentPanel::open(const json& args) {
  for (auto it = args.begin(); it != args.end(); ++it)
    if (it.key() != "assignment" && it.key() != "learner" && it.key() != "resume")
      throw ApiError("unknown field \"" + printable(it.key(), 40) + "\" (assignment, learner, resume)");
  if (!args.contains("assignment")) throw ApiError("assignment: required, an assignment file (an object or its JSON text)");
  const json& file = args["assignment"];
  AssignmentParse parsed = file.is_string() ? parse_assignment_text(file.get<std::string>()) : parse_assignment(file);
  const auto all = [](const std::string& head, const std::vector<std::string>& errors) {
    std::string m = head;
    for (std::size_t i = 0; i < errors.size(); ++i) m += (i ? "; " : "") + errors[i];
    return ApiError(m);
  };
  if (!parsed.assignment)
    throw all("assignment: " + std::to_string(parsed.errors.size()) + (parsed.errors.size() == 1 ? " problem: " : " problems: "),
              parsed.errors);
  const json learner = args.value("learner", json(""));
  if (!learner.is_string()) throw ApiError("learner: the learner's id, a string");
  AssignmentSession s;
  try {
    s = start_assignment_session(std::move(*parsed.assignment), learner.get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw ApiError(e.what());
  }
  if (args.contains("resume") && !args["resume"].is_null()) {
    const std::vector<std::string> errors = resume_session(s, args["resume"]);
    if (!errors.empty()) throw all("", errors);
  }
  session_ = std::move(s);
  preset_.clear();
  note_.clear();
  field_item_ = static_cast<std::size_t>(-1);
  want_confirm_ = false;
  web::dismiss_welcome();  // the assignment's card is the way in now: "Just explore" would mislead
  changed();
}

std::size_t AssignmentPanel::index_arg(const json& args) const {
  if (!session_) throw ApiError("no assignment is open (assignment_open first)");
  const json v = args.value("index", json());
  const std::size_t n = session_->assignment.items.size();
  if (!v.is_number_unsigned() || v.get<std::size_t>() >= n)
    throw ApiError("index: an item's index, 0 to " + std::to_string(n - 1));
  return v.get<std::size_t>();
}

void AssignmentPanel::go(std::size_t index) {
  const AssignmentItem& item = session_->assignment.items.at(index);
  const bool first = preset_.insert(index).second;  // the item's setup once: later visits keep the student's work
  if (item.kind == AssignmentItemKind::Exercise) {
    // The problem's lesson with its scene and parameters, as the homework map opens it; the
    // exercise itself is answered in this card (the View tab stays where it is on a phone).
    const HomeworkProblem* p = find_homework_problem(item.problem);
    json setup{{"params", p->params}};
    if (!p->scene.empty()) setup["scene"] = scene_to_json(bundled_scene(p->scene));
    note_ = show_(p->lesson, setup, first, false);
  } else {
    json setup{{"params", item.params}};
    if (!item.scene.is_null()) setup["scene"] = item.scene;
    note_ = show_(item.lesson, setup, first, true);
  }
  session_->current = index;
  changed();
}

json AssignmentPanel::answer(std::size_t index, const std::optional<std::string>& text) {
  const AssignmentItem& item = session_->assignment.items.at(index);
  try {
    switch (item.kind) {
      case AssignmentItemKind::Exercise:
        if (!text) throw ApiError("answer: required for an exercise, what the student typed");
        record_exercise_answer(*session_, index, *text);
        break;
      case AssignmentItemKind::Explore:
        record_visit(*session_, index);
        break;
      case AssignmentItemKind::Task:
        if (text) throw ApiError("a task is checked from the lab's state: no answer");
        if (session_->submitted) throw ApiError("the assignment was submitted: its answers are final");
        record_task_state(*session_, index, state_of_(item.lesson));
        break;
    }
  } catch (const std::invalid_argument& e) {
    throw ApiError(e.what());
  }
  changed();
  return state_json()["items"][index];
}

void AssignmentPanel::submit() {
  if (session_->submitted) throw ApiError("the assignment was submitted already");
  session_->submitted = true;
  note_.clear();
  want_confirm_ = false;
  changed();
}

void AssignmentPanel::register_api(JsApi& api) {
  api.add("assignment_open",
          "open an assignment (replacing any): {assignment: the file (object or JSON text), learner?: id (the exercises' "
          "seeds), resume?: an earlier state's suspend} -> assignment_state; every problem of the file in one error",
          [this](const json& args) {
            open(args);
            return state_json();
          });
  // The Author view (web/lab-author.js) checks its draft with this: the same parser as
  // assignment_open and the CLI's validate, so the page repeats none of the rules.
  api.add("assignment_validate",
          "check an assignment file without opening it: {assignment: object or JSON text} -> {valid, errors: [one "
          "line each, naming the item and field], assignment?: the file normalised, max_points?}",
          [](const json& args) {
            for (auto it = args.begin(); it != args.end(); ++it)
              if (it.key() != "assignment") throw ApiError("unknown field \"" + printable(it.key(), 40) + "\" (assignment)");
            if (!args.contains("assignment")) throw ApiError("assignment: required, an assignment file (an object or its JSON text)");
            const json& file = args["assignment"];
            const AssignmentParse parsed = file.is_string() ? parse_assignment_text(file.get<std::string>()) : parse_assignment(file);
            json out = {{"valid", parsed.assignment.has_value()}, {"errors", parsed.errors}};
            if (parsed.assignment) {
              out["assignment"] = assignment_to_json(*parsed.assignment);
              out["max_points"] = parsed.assignment->max_points();
            }
            return out;
          });
  api.add("assignment_state",
          "the open assignment: {title, description, learner, pass, current, submitted, note, items: [{index, id, kind, "
          "title, prompt, points, problem?, status: open|answered|correct|incorrect|viewed, score, max, answer, feedback, "
          "tries, tries_allowed, tries_left, tries_text, expected?, explanation?}], grade: {raw, min, max, scaled, "
          "completed, passed}, interactions: [{id, type, description, learner_response, result, weighting, "
          "correct_response?}], answers (cspacelab assignment grade's), suspend} (docs/web.md)",
          [this](const json&) {
            if (!session_) throw ApiError("no assignment is open (assignment_open first)");
            return state_json();
          });
  api.add("assignment_go", "open item {index} in the lab (its lesson, scene and parameters the first time) -> assignment_state",
          [this](const json& args) {
            go(index_arg(args));
            return state_json();
          });
  api.add("assignment_answer",
          "check and record item {index}: an exercise's {answer} text; a task from its lesson's state() now; an explore "
          "item as viewed -> the item {status, score, max, feedback, ...}",
          [this](const json& args) {
            const std::size_t index = index_arg(args);
            std::optional<std::string> text;
            if (args.contains("answer")) {
              const json& a = args["answer"];
              if (!a.is_string() && !a.is_number()) throw ApiError("answer: a string or a number");
              text = a.is_string() ? a.get<std::string>() : a.dump();
            }
            return answer(index, text);
          });
  api.add("assignment_submit", "submit: the answers become final, the review shows the right ones -> assignment_state",
          [this](const json&) {
            if (!session_) throw ApiError("no assignment is open (assignment_open first)");
            submit();
            return state_json();
          });
  api.add("assignment_close", "close the assignment (the lab stays as it is)", [this](const json&) {
    const bool was = session_.has_value();
    session_.reset();
    note_.clear();
    if (was) changed();
    return json(was);
  });
}

// ---- the card ---------------------------------------------------------------------------------

void AssignmentPanel::act(const std::function<void()>& action) {
  try {
    note_.clear();
    action();
  } catch (const std::exception& e) {
    // Refused (the lesson not open yet or still working, an answer too long to be saved):
    // nothing was recorded; the card says why. Never out of the frame.
    note_ = e.what();
  }
}

void AssignmentPanel::visit(std::size_t index) {
  act([&] {
    go(index);
    // An explore item asks to be looked at: going there through the card is the visit.
    if (session_->assignment.items[index].kind == AssignmentItemKind::Explore) answer(index, std::nullopt);
  });
}

void AssignmentPanel::card() {
  if (!session_) return;
  // The answer field follows the item on screen (and an answer set through the API).
  const std::size_t cur = session_->current;
  if (field_item_ != cur) {
    field_item_ = cur;
    const auto& a = session_->answers[cur];
    std::snprintf(answer_, sizeof answer_, "%s", a ? a->text.c_str() : "");
    focus_answer_ = session_->assignment.items[cur].kind == AssignmentItemKind::Exercise && !session_->submitted;
  }
  ImGui::PushID("assignment");
  card::boxed(theme::kCardProblem, [&] {
    const json& g = state_["grade"];
    ImGui::TextColored(theme::vec4(theme::kTextKey), "Assignment");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", session_->assignment.title.c_str());
    std::size_t done = 0;
    for (const json& it : state_["items"]) done += it["status"] != "open";
    const std::size_t n = state_["items"].size();
    // "answered", not "done": a wrong answer is recorded, not finished with. Once submitted the
    // count says nothing new, and the bar's centred text must fit the panel (it lost its first
    // characters): the score and the verdict only.
    const std::string score = "score " + points_text(g["raw"].get<double>()) + " of " + points_text(g["max"].get<double>());
    const std::string progress = !session_->submitted ? std::to_string(done) + " of " + std::to_string(n) + " answered, " + score
                                 : "submitted: " + score + (g["passed"] == true ? ", passed" : ", not passed");
    ImGui::ProgressBar(n ? static_cast<float>(done) / static_cast<float>(n) : 0.0f, ImVec2(-FLT_MIN, 0), progress.c_str());
    web::record_control("assignment-progress");
    if (session_->submitted) {
      review();
    } else {
      item_list();
      ImGui::Separator();
      current_item();
    }
    navigation();
#ifdef __EMSCRIPTEN__
    // Tab on the canvas steps between the app's fields only (ImGui 1.86 cannot tab to a button);
    // the page's copy of this card (lab-assignment-access.js) is where Tab goes next. Not said to
    // a finger, which has no Tab.
    if (!input::touch()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("By keyboard: Esc, then Tab, brings this card up as a page of buttons.");
      ImGui::PopStyleColor();
    }
#endif
  });
  submit_confirmation();
  ImGui::PopID();
  ImGui::Spacing();
}

void AssignmentPanel::item_list() {
  const json items = state_["items"];  // a copy: go() below changes state_
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string status = items[i]["status"].get<std::string>();
    const StatusLook look = status_look(status);
    const AssignmentItem& item = session_->assignment.items[i];
    char label[320];
    // The status before the title: a row cut at the panel's edge still says it.
    std::snprintf(label, sizeof label, "%s %zu. (%s) %s##item%zu", look.mark, i + 1, look.word, item.title.c_str(), i);
    const bool good = status == "correct" || status == "viewed", bad = status == "incorrect";
    if (good || bad) ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(good ? theme::kTextGood : theme::kTextBad));
    // A finger's row is a button's height (a text line, 23 px, is under the 24 px of WCAG 2.5.8).
    if (ImGui::Selectable(label, i == session_->current, 0, ImVec2(0, input::touch() ? ImGui::GetFrameHeight() : 0.0f)))
      visit(i);
    if (good || bad) ImGui::PopStyleColor();
    web::record_control(("assignment-item-" + std::to_string(i)).c_str());
  }
}

void AssignmentPanel::current_item() {
  const std::size_t i = session_->current;
  const AssignmentItem& item = session_->assignment.items[i];
  const json st = state_["items"][i];  // a copy: a click below changes state_
  ImGui::TextColored(theme::vec4(theme::kTextKey), "%zu.", i + 1);
  ImGui::SameLine();
  ImGui::TextWrapped("%s (%s %s)", item.title.c_str(), points_text(item.points).c_str(), item.points == 1 ? "point" : "points");
  card::paragraphs(st["prompt"].get<std::string>());
  // Used up, the answer is final: the field and its check are shown, disabled, with the feedback.
  const bool final_answer = st["tries_left"] == 0;
  if (item.kind == AssignmentItemKind::Exercise) {
    ImGui::BeginDisabled(final_answer);
    if (final_answer) focus_answer_ = false;
    const bool check = card::answer_row("##assignment-answer", st["format_hint"].get<std::string>(), answer_, sizeof answer_,
                                        focus_answer_, "assignment-answer", "assignment-check");
    ImGui::EndDisabled();
    if (check) {
      act([&] { answer(i, std::string(answer_)); });
      focus_answer_ = true;  // correct it and press Enter again
    }
    if (ui::small_button("Open the tool")) visit(i);
    web::record_control("assignment-open-item");
  } else {
    if (item.kind == AssignmentItemKind::Task) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("What counts: %s", st["check_text"].get<std::string>().c_str());
      ImGui::PopStyleColor();
    }
    if (ImGui::Button("Open in the lab")) visit(i);
    web::record_control("assignment-open-item");
    if (item.kind == AssignmentItemKind::Task) {
      ui::flow(ui::button_width("Check my lab"));
      ImGui::BeginDisabled(final_answer);
      if (ImGui::Button("Check my lab")) act([&] { answer(i, std::nullopt); });
      web::record_control("assignment-check-lab");
      ImGui::EndDisabled();
    }
  }
  if (const std::string tries = st["tries_text"].get<std::string>(); !tries.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", tries.c_str());
    ImGui::PopStyleColor();
  }
  const std::string feedback = st["feedback"].get<std::string>();
  if (!feedback.empty()) {
    const std::string status = st["status"].get<std::string>();
    const bool good = status == "correct" || status == "viewed";
    ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(good ? theme::kTextGood : theme::kTextBad));
    card::paragraphs(feedback);
    ImGui::PopStyleColor();
  }
  if (!note_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", note_.c_str());
    ImGui::PopStyleColor();
  }
}

void AssignmentPanel::review() {
  const json& st = state_;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Review: your answers, the right ones and how to get there");
  ImGui::PopStyleColor();
  for (const json& it : st["items"]) {
    ImGui::Separator();
    const std::string status = it["status"].get<std::string>();
    const bool good = status == "correct" || status == "viewed";
    ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(good ? theme::kTextGood : theme::kTextBad));
    ImGui::TextWrapped("%zu. %s: %s of %s (%s)", it["index"].get<std::size_t>() + 1, it["title"].get<std::string>().c_str(),
                       points_text(it["score"].get<double>()).c_str(), points_text(it["max"].get<double>()).c_str(),
                       status_look(status).word);
    ImGui::PopStyleColor();
    const std::string kind = it["kind"].get<std::string>();
    if (kind == "exercise") {
      card::paragraphs(it["prompt"].get<std::string>());
      ImGui::TextWrapped("Your answer: %s", it["answer"].is_string() ? it["answer"].get<std::string>().c_str() : "(none)");
      ImGui::TextWrapped("The right answer: %s", it["expected_text"].get<std::string>().c_str());
    } else if (kind == "task") {
      ImGui::TextWrapped("What counts: %s", it["check_text"].get<std::string>().c_str());
    }
    if (const std::string tries = it["tries_text"].get<std::string>(); !tries.empty()) ImGui::TextWrapped("%s", tries.c_str());
    card::paragraphs(it["explanation"].get<std::string>());
  }
}

void AssignmentPanel::navigation() {
  ImGui::Spacing();
  const std::size_t cur = session_->current, n = session_->assignment.items.size();
  ImGui::BeginDisabled(session_->submitted || cur == 0);
  if (ImGui::Button("\xE2\x97\x80 Previous")) visit(cur - 1);  // ◀
  web::record_control("assignment-prev");
  ImGui::EndDisabled();
  ui::flow(ui::button_width("Next \xE2\x96\xB6"));
  ImGui::BeginDisabled(session_->submitted || cur + 1 >= n);
  if (ImGui::Button("Next \xE2\x96\xB6")) visit(cur + 1);
  web::record_control("assignment-next");
  ImGui::EndDisabled();
  if (!session_->submitted) {
    ui::flow(ui::button_width("Submit..."));
    if (ImGui::Button("Submit...")) want_confirm_ = true;
    web::record_control("assignment-submit");
  }
}

void AssignmentPanel::submit_confirmation() {
  if (want_confirm_) {
    ImGui::OpenPopup("Submit the assignment?");
    want_confirm_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(320.0f, vp->WorkSize.x - 16), 0),
                                      ImVec2(std::max(320.0f, vp->WorkSize.x * 0.8f), FLT_MAX));
  if (!ImGui::BeginPopupModal("Submit the assignment?", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
    return;
  std::size_t open = 0;
  for (const json& it : state_["items"]) open += it["status"] == "open";
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::min(420.0f, vp->WorkSize.x - 48));
  ImGui::TextWrapped("Submit your answers? They become final, and the review shows the right ones.");
  if (open) ImGui::TextWrapped("%zu of %zu items have no answer yet.", open, state_["items"].size());
  ImGui::PopTextWrapPos();
  ImGui::Spacing();
  if (ImGui::Button("Submit")) {
    act([&] { submit(); });
    ImGui::CloseCurrentPopup();
  }
  web::record_control("assignment-submit-confirm");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  web::record_control("assignment-submit-cancel");
  if (cancel || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace csl::app
