#include "app/shell/homework_panel.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "app/shell/bundled_scenes.hpp"
#include "app/shell/card.hpp"
#include "app/shell/input_mode.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "imgui.h"

namespace csl::app {

using json = nlohmann::json;

namespace {

// Which of the 3-D lesson's two spaces an answered notation exercise's robot has: SE(2) (P1's
// robot that slides and turns, and an arm of two prismatic joints and one revolute, R^2 x S^1
// like it) or the revolute 3-link arm's T^3. Other arms (T^2 x R, R^3) the lesson does not draw,
// so no button rather than the picture of another space.
struct Space3d {
  const char* scene = nullptr;  ///< the bundled scene the lesson opens with
  const char* label = "";
};
Space3d space_in_3d(const Exercise& e) {
  if (e.robot == "base=planar") return {"polygon-robot", "See SE(2) in 3-D"};
  const std::string prefix = "joints=";
  if (e.robot.rfind(prefix, 0) != 0 || e.robot.size() != prefix.size() + 3) return {};
  const std::string joints = e.robot.substr(prefix.size());
  const auto revolute = std::count(joints.begin(), joints.end(), 'R');
  if (revolute == 3) return {"arm-3link", "See this arm's T\xc2\xb3 in 3-D"};
  if (revolute == 1) return {"polygon-robot", "See R\xc2\xb2 \xc3\x97 S\xc2\xb9 in 3-D (as SE(2))"};
  return {};
}

std::uint64_t seed_arg(const json& args) {
  const json& v = args["seed"];
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() > kMaxExerciseSeed)
    throw ApiError("seed: an integer in [0, 2^53 - 1]");
  return v.get<std::uint64_t>();
}

const HomeworkProblem& problem_arg(const json& args) {
  const json& v = args.contains("id") ? args["id"] : json();
  const HomeworkProblem* p = v.is_string() ? find_homework_problem(v.get<std::string>()) : nullptr;
  if (!p) throw ApiError("id: a problem of the homework, \"P1\" to \"P13\"");
  return *p;
}

}  // namespace

HomeworkPanel::HomeworkPanel(std::function<void(const HomeworkProblem&, bool)> open,
                             std::function<void(const std::string&, const json&)> show)
    : open_(std::move(open)), show_(std::move(show)) {}

std::uint64_t HomeworkPanel::fresh_seed() {
  // Each visit its own numbers; a link's &seed= fixes them (an instructor's worked example).
  // From the moment of the click (std::random_device would add the page's crypto glue to the
  // JS budget for this alone), mixed like splitmix64.
  static std::uint64_t counter = 0;
  std::uint64_t z = static_cast<std::uint64_t>(ImGui::GetTime() * 1e6) + 0x9E3779B97F4A7C15ull * ++counter;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (z ^ (z >> 31)) % 1000000;
}

void HomeworkPanel::set_exercise(const std::string& id, std::uint64_t seed) {
  try {
    exercise_ = make_exercise(id, seed);
  } catch (const std::invalid_argument& e) {
    throw ApiError(e.what());
  }
  checked_.reset();
  checked_answer_.clear();
  reveal_result_ = 0;
  answer_[0] = '\0';
  focus_answer_ = true;
}

void HomeworkPanel::open(const std::string& id, std::optional<std::uint64_t> seed, bool preset) {
  const HomeworkProblem* p = find_homework_problem(id);
  if (!p) throw ApiError("id: a problem of the homework, \"P1\" to \"P13\"");
  if (seed && *seed > kMaxExerciseSeed) throw ApiError("seed: an integer in [0, 2^53 - 1]");
  open_(*p, preset);  // may throw: the panel has not changed yet
  problem_ = p->id;
  set_exercise(p->id, seed ? *seed : fresh_seed());
  web::dismiss_welcome();
}

json HomeworkPanel::check(const std::string& answer) {
  if (!exercise_) throw ApiError("no exercise is open (open_problem or exercise first)");
  checked_ = check_exercise(*exercise_, answer);
  checked_answer_ = answer;
  reveal_result_ = 2;
  // The score counts answers the lab could read, and each exercise answered right once.
  Score& s = scores_[exercise_->id];
  if (checked_->readable) ++s.tried;
  if (checked_->correct && solved_.insert({exercise_->id, exercise_->seed}).second) ++s.right;
  // reveal=after-answer: only an exercise answered right before the student asked for its
  // solution, so that reading the answer off the solution reveals nothing.
  // A typical mistake's reason can all but give the answer ("the sign is wrong"): as shown.
  if (checked_->typical_mistake) shown_.insert({exercise_->id, exercise_->seed});
  if (checked_->correct && !solution_shown()) instructor::solved(exercise_->id);
  return exercise_check_to_json(*checked_);
}

bool HomeworkPanel::solution_shown() const { return exercise_ && shown_.count({exercise_->id, exercise_->seed}); }

bool HomeworkPanel::solution_offered() const {
  return checked_ && checked_->readable && !checked_->correct && !solution_shown();
}

json HomeworkPanel::show_solution() {
  if (!exercise_ || !checked_ || !checked_->readable) throw ApiError("try an answer first: the solution is shown after a try");
  shown_.insert({exercise_->id, exercise_->seed});
  return {{"explanation", checked_->explanation}, {"expected", checked_->expected}};
}

json HomeworkPanel::show_in_tool() {
  if (!exercise_ || !checked_) throw ApiError("answer the exercise first: its numbers are shown once it was checked");
  const json setup = exercise_tool_setup(*exercise_);
  if (setup.is_null()) throw ApiError(exercise_->id + "'s numbers do not go into a tool");
  show_(find_homework_problem(exercise_->id)->lesson, setup);
  return setup;
}

json HomeworkPanel::show_in_3d() {
  if (!exercise_ || !checked_) throw ApiError("answer the exercise first: its C-space is shown once it was checked");
  const Space3d view = space_in_3d(*exercise_);
  if (!view.scene) throw ApiError(exercise_->id + ": the 3-D lesson has no picture of this robot's C-space");
  show_("cspace-3d", {{"scene", scene_to_json(bundled_scene(view.scene))}});
  return {{"lesson", "cspace-3d"}};
}

json HomeworkPanel::state_json() const {
  const Space3d view = exercise_ ? space_in_3d(*exercise_) : Space3d{};
  json scores = json::object();
  for (const auto& [id, s] : scores_) scores[id] = {{"tried", s.tried}, {"right", s.right}};
  json out{{"problem", problem_.empty() ? json(nullptr) : json(problem_)},
           {"exercise", exercise_ ? exercise_to_json(*exercise_) : json(nullptr)},
           {"answer", std::string(answer_)},
           {"check", checked_ ? exercise_check_to_json(*checked_) : json(nullptr)},
           {"solution_shown", solution_shown()},
           // The card shows the check's feedback and a Show the solution button, else its explanation.
           {"solution_offered", solution_offered()},
           {"scores", scores},
           // What the card offers once answered (the page's copy, lab-homework-access.js, too).
           {"tool", checked_ && !exercise_tool_setup(*exercise_).is_null()},
           {"see_3d", checked_ && view.scene ? json(view.label) : json(nullptr)},
           {"error", error_},
           {"map_open", map_open_},
           {"welcome", web::page().welcome}};
  return out;
}

void HomeworkPanel::register_api(JsApi& api) {
  api.add("homework", "the handout's problems: [{id, title, lesson, task}] for P1 to P13", [](const json&) {
    json out = json::array();
    for (const HomeworkProblem& p : homework_problems())
      out.push_back({{"id", p.id}, {"title", p.title}, {"lesson", p.lesson}, {"task", p.task}});
    return out;
  });
  api.add("open_problem", "open a problem's lesson and exercise: {id: 'P10', seed?, preset?: false keeps the lesson's scene}", [this](const json& args) {
    const HomeworkProblem& p = problem_arg(args);
    const json& preset = args.contains("preset") ? args["preset"] : json(true);
    if (!preset.is_boolean()) throw ApiError("preset: true or false");
    const bool has_seed = args.contains("seed") && !args["seed"].is_null();
    open(p.id, has_seed ? std::optional<std::uint64_t>(seed_arg(args)) : std::nullopt, preset.get<bool>());
    return state_json();
  });
  api.add("exercise", "a problem's exercise {id, seed?}, made the current one: {id, seed, prompt, given, answer_format, format_hint}",
          [this](const json& args) {
            const HomeworkProblem& p = problem_arg(args);
            set_exercise(p.id, args.contains("seed") ? seed_arg(args) : fresh_seed());
            problem_ = p.id;  // the card shows it when its lesson is on screen
            return exercise_to_json(*exercise_);
          });
  api.add("check_answer", "check an answer to the current exercise: {answer} -> {correct, expected, explanation, feedback}",
          [this](const json& args) {
            const json& a = args.contains("answer") ? args["answer"] : json();
            if (!(a.is_string() || a.is_number()) || (a.is_string() && a.get<std::string>().size() > 200))
              throw ApiError("answer: a string (at most 200 characters) or a number");
            const std::string text = a.is_string() ? a.get<std::string>() : a.dump();
            std::snprintf(answer_, sizeof answer_, "%s", text.c_str());
            return check(text);
          });
  api.add("show_exercise", "after an answer was checked: the exercise's numbers in its lesson; {in: '3d'}: its robot's C-space in the 3-D lesson",
          [this](const json& args) {
            const json& in = args.contains("in") ? args["in"] : json("tool");
            if (in != "tool" && in != "3d") throw ApiError("in: 'tool' or '3d'");
            return in == "3d" ? show_in_3d() : show_in_tool();
          });
  api.add("show_solution", "after a try: the exercise's answer and worked solution, as the card's Show the solution "
          "(with reveal=after-answer, a right answer after it does not count) -> {explanation, expected}",
          [this](const json&) { return show_solution(); });
  api.add("close_problem", "close the problem's card, as its Close button (the lesson stays)", [this](const json&) {
    problem_.clear();
    return state_json();
  });
  api.add("homework_state", "the open problem, its exercise, the last check and the visit's scores",
          [this](const json&) { return state_json(); });
}

void HomeworkPanel::menu_button(bool tall) {
  if (ui::bar_button("Homework", tall) || want_map_) {
    want_map_ = false;
    ImGui::OpenPopup("homework-map");
    web::dismiss_welcome();
  }
  web::record_control("homework");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the handout's problems P1 to P13: each opens its tool and an exercise");
  map_open_ = ImGui::BeginPopup("homework-map");
  if (!map_open_) return;
  // On a phone the longest titles are wider than the screen: a row wraps within it (ImGui's
  // Selectable does not wrap, so the text is drawn over it), and is a finger's height by touch.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float wrap = ImGui::GetMainViewport()->WorkSize.x - 2 * (style.WindowPadding.x + style.DisplaySafeAreaPadding.x) - 8;
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
  ImGui::TextDisabled("The handout's problems: choose one to open its tool and an exercise");
  ImGui::PopTextWrapPos();
  ImGui::Separator();
  for (const HomeworkProblem& p : homework_problems()) {
    const auto s = scores_.find(p.id);
    char label[256];
    std::snprintf(label, sizeof label, "%-4s %s%s", p.id.c_str(), p.title.c_str(),
                  s == scores_.end() ? "" : s->second.right > 0 ? "   \xE2\x9C\x93" : "   (tried)");
    // A row that fits spans the map's width (0), as a Selectable does; one that does not, the screen's.
    const float natural = ImGui::CalcTextSize(label).x;
    const bool fits = natural <= wrap;
    const float width = fits ? natural : wrap;
    const ImVec2 text = ImGui::CalcTextSize(label, nullptr, false, width);
    const ImVec2 at = ImGui::GetCursorPos();
    const bool chosen = ImGui::Selectable(("##" + p.id).c_str(), p.id == problem_, 0,
                                          ImVec2(fits ? 0.0f : width, std::max(text.y, input::touch() ? ImGui::GetFrameHeight() : 0.0f)));
    web::record_control(("problem-" + p.id).c_str());
    const ImVec2 next = ImGui::GetCursorPos();
    ImGui::SetCursorPos(ImVec2(at.x, at.y + std::max(0.0f, (ImGui::GetItemRectSize().y - text.y) * 0.5f)));
    ImGui::PushTextWrapPos(at.x + width);
    ImGui::TextUnformatted(label);
    ImGui::PopTextWrapPos();
    ImGui::SetCursorPos(next);
    if (chosen) {
      try {
        open(p.id, std::nullopt);
        error_.clear();
      } catch (const std::exception& x) {
        // The lesson refused its preset (it should not, with the bundled scenes): stay here, say why.
        error_ = p.id + " could not be opened: " + x.what();
      }
      ImGui::CloseCurrentPopup();
    }
  }
  ImGui::EndPopup();
}

void HomeworkPanel::card(const std::string& lesson_id) {
  if (web::page().welcome && problem_.empty()) {
    card::boxed(theme::kCardWelcome, [&] {
    // Short: a first visit's panel must still fit 1280 x 800 with it (tests/e2e/panel-layout).
    ImGui::TextWrapped("Welcome! Homework P1 to P13: each has a tool here, and an exercise the lab checks.");
    if (ImGui::Button("Open the homework map")) {
      web::dismiss_welcome();
      want_map_ = true;  // opened by menu_button(), where the map's popup lives
    }
    web::record_control("welcome-map");
    ui::flow(ui::button_width("Just explore"));
    if (ImGui::Button("Just explore")) web::dismiss_welcome();
    web::record_control("welcome-dismiss");
    });
    ImGui::Spacing();
  }
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(theme::kTextBad));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
  }
  if (problem_.empty() || !exercise_ || exercise_->id != problem_) return;
  const HomeworkProblem* p = find_homework_problem(problem_);
  if (!p || p->lesson != lesson_id) return;

  ImGui::PushID("homework");  // its Check and answer field apart from a lesson's own
  card::boxed(theme::kCardProblem, [&] { problem_body(*p); });
  ImGui::PopID();
  ImGui::Spacing();
}

void HomeworkPanel::problem_body(const HomeworkProblem& problem) {
  const HomeworkProblem* p = &problem;
  ImGui::TextColored(theme::vec4(theme::kTextKey), "%s", p->id.c_str());
  ImGui::SameLine();
  ImGui::TextWrapped("%s", p->title.c_str());
  ImGui::TextWrapped("%s", p->task.c_str());
  ImGui::Separator();
  const Exercise& e = *exercise_;
  ImGui::TextDisabled("Exercise %s, numbers no. %llu", e.id.c_str(), static_cast<unsigned long long>(e.seed));
  card::paragraphs(e.prompt);
  if (card::answer_row("##homework-answer", e.format_hint, answer_, sizeof answer_, focus_answer_, "answer", "check")) {
    check(answer_);
    focus_answer_ = true;  // correct it and press Enter again
  }
  // Where the result starts and where the buttons it brings end (screen y).
  const float result_top = ImGui::GetCursorScreenPos().y;
  float result_bottom = result_top;
  const auto result_end = [&] { result_bottom = ImGui::GetItemRectMax().y; };
  if (checked_) {
    // A wrong try is told what went wrong, not the answer: another try, or the solution on request.
    const bool whole = !solution_offered();
    const std::string& text = whole ? checked_->explanation : checked_->feedback;
    const std::size_t cut = text.find('\n');
    ImGui::PushStyleColor(ImGuiCol_Text, checked_->correct ? theme::vec4(theme::kTextGood) : theme::vec4(theme::kTextBad));
    ImGui::TextWrapped("%s", text.substr(0, cut).c_str());
    ImGui::PopStyleColor();
    result_end();
    if (cut != std::string::npos) card::paragraphs(text.substr(cut + 1));
    result_end();
    if (!whole) {
      if (ui::small_button("Show the solution")) show_solution();
      web::record_control("show-solution");
      result_end();
    }
  }
  // Predict, then reveal: the exercise's numbers go into the tool once the student has answered.
  if (checked_ && !exercise_tool_setup(e).is_null()) {
    if (ui::small_button("Show these numbers in the tool")) {
      try {
        show_in_tool();
        error_.clear();
      } catch (const std::exception& x) {
        error_ = std::string("The lesson did not take these numbers: ") + x.what();  // nothing changed
      }
    }
    web::record_control("show-in-tool");
    result_end();
  }
  // P1, P2 and P5 are answered in notation; once answered (the lesson's title would give the
  // answer away before), the C-space itself, when the 3-D lesson has this robot's space.
  if (const Space3d view = space_in_3d(e); checked_ && view.scene) {
    if (ui::small_button(view.label)) {
      try {
        show_in_3d();
        error_.clear();
      } catch (const std::exception& x) {
        error_ = std::string("The 3-D lesson did not open: ") + x.what();  // an instructor's lock=lesson, say
      }
    }
    web::record_control("see-in-3d");
    result_end();
  }
  if (checked_ && reveal_result_ > 0) {
    // The card is taller than a phone on its side: a check's result and "Show these numbers in
    // the tool" were under the panel's bottom edge, and a student who did not know to swipe did
    // not see them. Scrolled up just so far that its last button is on screen, but never past
    // the verdict's first line ("Right.", "Not right yet."): where both do not fit, the verdict.
    --reveal_result_;
    const float pad = ImGui::GetStyle().ItemSpacing.y;
    const float top = ImGui::GetWindowPos().y, bottom = top + ImGui::GetWindowHeight();
    const float below = std::min(result_bottom + pad - bottom, result_top - pad - top);
    if (below > 0.5f) ImGui::SetScrollY(ImGui::GetScrollY() + below);
  }
  if (ui::small_button("New numbers")) set_exercise(e.id, fresh_seed());
  web::record_control("new-numbers");
  const auto s = scores_.find(e.id);
  if (s != scores_.end()) {
    // Two counts of different things (exercises solved, answers checked): "1 of 2 right" read as
    // a share of answers, which it is not once an exercise is answered right twice.
    const int right = s->second.right, tried = s->second.tried;
    ui::flow(ImGui::CalcTextSize("this visit: 00 solved in 00 tries").x);
    ImGui::TextDisabled("this visit: %d solved in %d %s", right, tried, tried == 1 ? "try" : "tries");
  }
  ui::flow(ui::button_width("Close"));
  if (ui::small_button("Close")) problem_.clear();
}

}  // namespace csl::app
